#include "estimator/noise/mean_removal.hpp"

namespace sinu::noise {

double series_mean(std::span<const double> x) {
  if (x.empty()) return 0.0;
  double sum = 0.0, carry = 0.0;  // Kahan summation
  for (double v : x) {
    const double y = v - carry;
    const double t = sum + y;
    carry = (t - sum) - y;
    sum = t;
  }
  return sum / static_cast<double>(x.size());
}

std::vector<double> remove_mean(std::span<const double> x, double& turn_on_bias) {
  turn_on_bias = series_mean(x);
  std::vector<double> out(x.begin(), x.end());
  for (double& v : out) v -= turn_on_bias;
  return out;
}

}  // namespace sinu::noise
