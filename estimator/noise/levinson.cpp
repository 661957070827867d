#include "estimator/noise/levinson.hpp"

namespace sinu::noise {

std::vector<double> step_up(const std::vector<double>& a, double k) {
  const std::size_t p = a.size();
  std::vector<double> next(p + 1);
  next[0] = 1.0;
  for (std::size_t i = 1; i < p; ++i) next[i] = a[i] + k * a[p - i];
  next[p] = k;
  return next;
}

std::vector<ArModel> levinson_durbin(std::span<const double> r, std::size_t max_order) {
  std::vector<ArModel> models;
  if (r.empty() || !(r[0] > 0.0) || r.size() <= max_order) return models;
  std::vector<double> a{1.0};
  double err = r[0];
  for (std::size_t p = 1; p <= max_order; ++p) {
    double acc = r[p];
    for (std::size_t i = 1; i < p; ++i) acc += a[i] * r[p - i];
    const double k = -acc / err;
    a = step_up(a, k);
    err *= 1.0 - k * k;
    models.push_back(ArModel{a, err});
  }
  return models;
}

}  // namespace sinu::noise
