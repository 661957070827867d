#include "estimator/noise/allan_noise_terms.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>

namespace sinu::noise {

namespace {

constexpr int kTerms = 5;  // tau^-2, tau^-1, tau^0, tau^1, tau^2

double basis(int term, double tau) { return std::pow(tau, term - 2); }

}  // namespace

double AllanNoiseTerms::model_adev(double tau_s) const {
  const double flicker = B_fit * kFlickerAdevFactor;
  const double avar = 3.0 * Q * Q / (tau_s * tau_s) + N * N / tau_s + flicker * flicker +
                      K * K * tau_s / 3.0 + R * R * tau_s * tau_s / 2.0;
  return std::sqrt(avar);
}

AllanNoiseTerms fit_allan_noise_terms(std::span<const AllanPoint> curve) {
  AllanNoiseTerms t;
  const auto rows = static_cast<Eigen::Index>(curve.size());
  if (rows < kTerms) return t;
  Eigen::MatrixXd a(rows, kTerms);
  Eigen::VectorXd b(rows);
  for (Eigen::Index i = 0; i < rows; ++i) {
    const AllanPoint& p = curve[static_cast<std::size_t>(i)];
    const double avar = p.adev * p.adev;
    if (!(avar > 0.0)) return t;
    const double w = std::sqrt(p.edf) / avar;
    for (int j = 0; j < kTerms; ++j) a(i, j) = w * basis(j, p.tau_s);
    b(i) = w * avar;
  }
  // Exact NNLS for five unknowns: the best feasible unconstrained solution over
  // all 31 non-empty subsets of active terms.
  double best_cost = std::numeric_limits<double>::infinity();
  Eigen::VectorXd best = Eigen::VectorXd::Zero(kTerms);
  for (int mask = 1; mask < (1 << kTerms); ++mask) {
    Eigen::MatrixXd sub(rows, __builtin_popcount(static_cast<unsigned>(mask)));
    int c = 0;
    for (int j = 0; j < kTerms; ++j)
      if (mask & (1 << j)) sub.col(c++) = a.col(j);
    const Eigen::VectorXd x = sub.colPivHouseholderQr().solve(b);
    if ((x.array() < 0.0).any() || !x.allFinite()) continue;
    const double cost = (sub * x - b).squaredNorm();
    if (cost < best_cost) {
      best_cost = cost;
      best.setZero();
      c = 0;
      for (int j = 0; j < kTerms; ++j)
        if (mask & (1 << j)) best(j) = x(c++);
    }
  }
  if (!std::isfinite(best_cost)) return t;
  t.Q = std::sqrt(best(0) / 3.0);
  t.N = std::sqrt(best(1));
  t.B_fit = std::sqrt(best(2)) / kFlickerAdevFactor;
  t.K = std::sqrt(3.0 * best(3));
  t.R = std::sqrt(2.0 * best(4));
  // The flat part IEEE 952 reads B from: the first local minimum of the curve
  // (lower than its predecessor and not above its next two points); a curve
  // that keeps falling has none, and then its global minimum is used (B is
  // then an upper bound and the report says the floor was not reached).
  double min_adev = std::numeric_limits<double>::infinity();
  std::size_t at = 0;
  for (std::size_t i = 1; i + 2 < curve.size(); ++i) {
    if (curve[i].adev < curve[i - 1].adev && curve[i].adev <= curve[i + 1].adev &&
        curve[i].adev <= curve[i + 2].adev) {
      at = i;
      min_adev = curve[i].adev;
      t.floor_reached = true;
      break;
    }
  }
  if (!t.floor_reached) {
    for (std::size_t i = 0; i < curve.size(); ++i) {
      if (curve[i].adev < min_adev) min_adev = curve[i].adev, at = i;
    }
  }
  t.B_tau_s = curve[at].tau_s;
  t.B = min_adev / kFlickerAdevFactor;
  t.valid = true;
  return t;
}

}  // namespace sinu::noise
