#include "estimator/noise/ar_model.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <numbers>

namespace sinu::noise {

std::vector<double> ar_autocorrelation(const ArModel& model, std::size_t max_lag) {
  const std::size_t p = model.order();
  if (model.a.empty()) return {};
  // Unknowns r(0..p): for k = 0..p, sum_{i=0}^{p} a_i r(|k-i|) = variance * delta(k).
  const auto n = static_cast<Eigen::Index>(p + 1);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  rhs(0) = model.variance;
  for (std::size_t k = 0; k <= p; ++k) {
    for (std::size_t i = 0; i <= p; ++i) {
      const std::size_t lag = k >= i ? k - i : i - k;
      m(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(lag)) += model.a[i];
    }
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(m);
  if (!lu.isInvertible()) return {};
  const Eigen::VectorXd r0 = lu.solve(rhs);
  if (!(r0(0) > 0.0)) return {};
  std::vector<double> r(max_lag + 1, 0.0);
  for (std::size_t k = 0; k <= max_lag; ++k) {
    if (k <= p) {
      r[k] = r0(static_cast<Eigen::Index>(k));
      continue;
    }
    double s = 0.0;
    for (std::size_t i = 1; i <= p; ++i) s -= model.a[i] * r[k - i];
    r[k] = s;
  }
  return r;
}

double ar_psd_one_sided(const ArModel& model, double f_hz, double fs_hz) {
  std::complex<double> denom = 0.0;
  const double w = 2.0 * std::numbers::pi * f_hz / fs_hz;
  for (std::size_t k = 0; k < model.a.size(); ++k) {
    denom += model.a[k] * std::polar(1.0, -w * static_cast<double>(k));
  }
  return 2.0 * model.variance / fs_hz / std::norm(denom);
}

bool ar_is_stable(const ArModel& model) {
  std::vector<double> a = model.a;  // step-down (backward Levinson) recursion
  for (std::size_t p = model.order(); p >= 1; --p) {
    const double k = a[p];
    if (!(std::abs(k) < 1.0)) return false;
    std::vector<double> lower(p);
    lower[0] = 1.0;
    for (std::size_t i = 1; i < p; ++i) lower[i] = (a[i] - k * a[p - i]) / (1.0 - k * k);
    a = std::move(lower);
  }
  return true;
}

}  // namespace sinu::noise
