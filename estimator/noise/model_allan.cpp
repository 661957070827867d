#include "estimator/noise/model_allan.hpp"

#include <cmath>

namespace sinu::noise {

double allan_variance_of_autocovariance(std::span<const double> r, std::size_t m) {
  if (m == 0 || r.size() < 2 * m) return NAN;
  const double md = static_cast<double>(m);
  double var = md * r[0];
  for (std::size_t k = 1; k < m; ++k) var += 2.0 * (md - static_cast<double>(k)) * r[k];
  double cov = md * r[m];
  for (std::size_t k = 1; k < m; ++k) cov += (md - static_cast<double>(k)) * (r[m + k] + r[m - k]);
  return (var - cov) / (md * md);
}

}  // namespace sinu::noise
