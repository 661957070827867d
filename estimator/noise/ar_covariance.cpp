#include "estimator/noise/ar_covariance.hpp"

#include <Eigen/Dense>

namespace sinu::noise {

std::vector<ArModel> ar_covariance(std::span<const double> x, std::size_t max_order) {
  const std::size_t n = x.size();
  std::vector<ArModel> models;
  if (n <= 2 * max_order) return models;
  // full_lag[k] = sum_{m=k}^{N-1} x(m) x(m-k)
  std::vector<double> full_lag(max_order + 1, 0.0);
  for (std::size_t k = 0; k <= max_order; ++k) {
    double s = 0.0;
    for (std::size_t m = k; m < n; ++m) s += x[m] * x[m - k];
    full_lag[k] = s;
  }
  // C_p(i, j) = sum_{t=p}^{N-1} x(t-i) x(t-j) = sum_{m=p-i}^{N-1-i} x(m) x(m-k), k = j - i >= 0
  auto normal_entry = [&](std::size_t p, std::size_t i, std::size_t j) {
    if (j < i) std::swap(i, j);
    const std::size_t k = j - i;
    double s = full_lag[k];
    for (std::size_t m = k; m < p - i; ++m) s -= x[m] * x[m - k];
    for (std::size_t m = n - i; m < n; ++m) s -= x[m] * x[m - k];
    return s;
  };
  for (std::size_t p = 1; p <= max_order; ++p) {
    const auto ip = static_cast<Eigen::Index>(p);
    Eigen::MatrixXd c(ip + 1, ip + 1);
    for (std::size_t i = 0; i <= p; ++i) {
      for (std::size_t j = i; j <= p; ++j) {
        const double v = normal_entry(p, i, j);
        c(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = v;
        c(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) = v;
      }
    }
    const Eigen::VectorXd coef = c.bottomRightCorner(ip, ip).ldlt().solve(-c.col(0).tail(ip));
    if (!coef.allFinite()) break;
    ArModel m;
    m.a.resize(p + 1);
    m.a[0] = 1.0;
    for (std::size_t i = 1; i <= p; ++i) m.a[i] = coef(static_cast<Eigen::Index>(i - 1));
    // Residual power = C(0,0) + sum a_i C(0,i) (the residual is orthogonal to the regressors).
    double rss = c(0, 0);
    for (std::size_t i = 1; i <= p; ++i) rss += m.a[i] * c(0, static_cast<Eigen::Index>(i));
    m.variance = rss / static_cast<double>(n - p);
    models.push_back(std::move(m));
  }
  return models;
}

}  // namespace sinu::noise
