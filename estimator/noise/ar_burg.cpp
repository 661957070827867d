#include "estimator/noise/ar_burg.hpp"

#include "estimator/noise/levinson.hpp"

namespace sinu::noise {

std::vector<ArModel> ar_burg(std::span<const double> x, std::size_t max_order) {
  const std::size_t n = x.size();
  std::vector<ArModel> models;
  if (n <= max_order + 2) return models;
  // f(i) forward error at sample i+p, b(i) backward error at sample i; the
  // live region shrinks by one sample per order.
  std::vector<double> f(x.begin() + 1, x.end());
  std::vector<double> b(x.begin(), x.end() - 1);
  double v = 0.0;
  for (double s : x) v += s * s;
  v /= static_cast<double>(n);
  std::vector<double> a{1.0};
  std::size_t len = n - 1;
  for (std::size_t p = 1; p <= max_order; ++p) {
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < len; ++i) {
      num += b[i] * f[i];
      den += f[i] * f[i] + b[i] * b[i];
    }
    if (!(den > 0.0)) break;
    const double k = -2.0 * num / den;
    a = step_up(a, k);
    v *= 1.0 - k * k;
    models.push_back(ArModel{a, v});
      for (std::size_t i = 0; i + 1 < len; ++i) {
      const double f_old = f[i];  // f[i+1], b[i+1] are still this order's values
      f[i] = f[i + 1] + k * b[i + 1];
      b[i] += k * f_old;
    }
    --len;
  }
  return models;
}

}  // namespace sinu::noise
