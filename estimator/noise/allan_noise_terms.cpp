#include "estimator/noise/allan_noise_terms.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

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
  // The flat part IEEE 952 reads B from: points whose log-log slope (over
  // +-kSlopeSpan points) is within +-kFlatSlope, with enough averaging
  // (edf >= kMinEdf); the longest run of such points (a floor or a
  // Gauss-Markov crest spans decades, a dip before a rise or a periodic bump's
  // top a fraction of one), and its median ADEV. A curve with no flat run (still falling) gives its
  // global minimum: B is then an upper bound and floor_reached is false.
  constexpr std::size_t kSlopeSpan = 2;
  constexpr double kFlatSlope = 0.25;  // closer to 0 than to the white (-1/2) or RRW (+1/2) slope
  constexpr double kMinEdf = 10.0;
  std::vector<bool> flat(curve.size(), false);
  for (std::size_t i = kSlopeSpan; i + kSlopeSpan < curve.size(); ++i) {
    const AllanPoint& lo = curve[i - kSlopeSpan];
    const AllanPoint& hi = curve[i + kSlopeSpan];
    const double slope = std::log(hi.adev / lo.adev) / std::log(hi.tau_s / lo.tau_s);
    flat[i] = std::abs(slope) < kFlatSlope && curve[i].edf >= kMinEdf;
  }
  std::size_t best_begin = 0, best_len = 0;
  for (std::size_t i = 0; i < curve.size();) {
    if (!flat[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < curve.size() && flat[j]) ++j;
    if (j - i > best_len) best_begin = i, best_len = j - i;
    i = j;
  }
  t.floor_reached = best_len > 0;
  std::size_t at = 0;
  if (t.floor_reached) {
    // The run's median point: robust to the scatter of the long-tau points.
    std::vector<std::size_t> idx(best_len);
    for (std::size_t i = 0; i < best_len; ++i) idx[i] = best_begin + i;
    std::nth_element(idx.begin(), idx.begin() + static_cast<std::ptrdiff_t>(best_len / 2), idx.end(),
                     [&](std::size_t l, std::size_t r) { return curve[l].adev < curve[r].adev; });
    at = idx[best_len / 2];
  } else {
    for (std::size_t i = 1; i < curve.size(); ++i)
      if (curve[i].adev < curve[at].adev) at = i;
  }
  t.B_tau_s = curve[at].tau_s;
  t.B = curve[at].adev / kFlickerAdevFactor;
  t.valid = true;
  return t;
}

}  // namespace sinu::noise
