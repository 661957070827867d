#include "firmware/host/calibration/six_position.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "estimator/earth/wgs84.hpp"

namespace sinu::calibration {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kFreeAirGradient = 3.086e-6;  // [1/s^2]
constexpr std::array<std::array<Eigen::Index, 2>, 3> kPairs = {{{0, 1}, {0, 2}, {1, 2}}};
constexpr double kPairExcitation = 0.2;        // |u_i u_j| that makes a misalignment term visible
constexpr std::size_t kMinSegments = 6;

using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;

// Parameters: b (3), s (3), then the symmetric misalignments xy, xz, yz (when fitted).
Eigen::Matrix3d cross_axis(const Vec& p) {
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  if (p.size() == 9)
    for (std::size_t q = 0; q < 3; ++q) M(kPairs[q][0], kPairs[q][1]) = M(kPairs[q][1], kPairs[q][0]) = p[6 + static_cast<Eigen::Index>(q)];
  return M;
}

Eigen::Matrix3d scale_matrix(const Vec& p) {
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  S.diagonal() += p.segment<3>(3);
  return S;
}

struct Problem {
  const std::vector<SegmentMean>& seg;
  std::vector<double> sigma;  // per segment: the mean's uncertainty along gravity
  double g;

  // Weighted residuals, and (optionally) their Jacobian.
  void evaluate(const Vec& p, Vec& r, Mat* J) const {
    const Eigen::Matrix3d S = scale_matrix(p), IM = Eigen::Matrix3d::Identity() + cross_axis(p);
    const Eigen::Matrix3d K = (S * IM).inverse();
    const Eigen::Vector3d b = p.head<3>();
    const auto n = static_cast<Eigen::Index>(seg.size());
    r.resize(n);
    if (J) J->setZero(n, p.size());
    for (Eigen::Index k = 0; k < n; ++k) {
      const double w = 1.0 / sigma[static_cast<std::size_t>(k)];
      const Eigen::Vector3d y = K * (seg[static_cast<std::size_t>(k)].accel_m_s2 - b);
      const double ny = y.norm();
      r[k] = (ny - g) * w;
      if (!J) continue;
      // d|y| = u^T dy;  dy/db = -K;  dy/dtheta = -K (dG/dtheta) y.
      const Eigen::RowVector3d uK = (y / ny).transpose() * K;
      J->block(k, 0, 1, 3) = -w * uK;
      const Eigen::Vector3d IMy = IM * y;
      for (Eigen::Index i = 0; i < 3; ++i) (*J)(k, 3 + i) = -w * uK[i] * IMy[i];
      if (p.size() == 9) {
        for (std::size_t q = 0; q < 3; ++q) {
          const auto [i, j] = kPairs[q];
          Eigen::Vector3d v = Eigen::Vector3d::Zero();  // S (E_ij + E_ji) y
          v[i] = S(i, i) * y[j];
          v[j] = S(j, j) * y[i];
          (*J)(k, 6 + static_cast<Eigen::Index>(q)) = -w * uK.dot(v);
        }
      }
    }
  }
};

}  // namespace

double GravityModel::g_m_s2() const { return est::wgs84::normal_gravity_m_s2(latitude_deg * kDeg, height_m); }

double GravityModel::relative_sigma() const {
  const double g = g_m_s2();
  double var = 0.0;
  if (!latitude_given) {
    const double span = est::wgs84::normal_gravity_m_s2(0.5 * std::numbers::pi, height_m) -
                        est::wgs84::normal_gravity_m_s2(0.0, height_m);
    var += std::pow(span / g, 2) / 12.0;
  }
  if (!height_given) var += std::pow(kFreeAirGradient * kUnknownHeightSigma_m / g, 2);
  return std::sqrt(var);
}

Eigen::Matrix3d SixPositionFit::gain() const {
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  S.diagonal() += accel_scale_ppm * 1e-6;
  return S * (Eigen::Matrix3d::Identity() + accel_misalign_rad);
}

Eigen::Matrix3d SixPositionFit::correction() const { return gain().inverse(); }

bool misalignment_observable(const std::vector<SegmentMean>& segments) {
  if (segments.size() < 9) return false;
  for (const auto& [i, j] : kPairs) {
    double best = 0.0;
    for (const SegmentMean& s : segments) {
      const Eigen::Vector3d u = s.accel_m_s2.normalized();
      best = std::max(best, std::abs(u[i] * u[j]));
    }
    if (best < kPairExcitation) return false;
  }
  return true;
}

bool fit_six_position(const std::vector<SegmentMean>& segments, const GravityModel& gravity, SixPositionFit& fit,
                      std::string& why) {
  fit = SixPositionFit{};
  if (segments.size() < kMinSegments) {
    why = "a multi-position calibration needs at least 6 still segments, found " + std::to_string(segments.size());
    return false;
  }
  fit.misalign_fitted = misalignment_observable(segments);
  const Eigen::Index np = fit.misalign_fitted ? 9 : 6;
  Problem prob{segments, {}, gravity.g_m_s2()};
  for (const SegmentMean& s : segments) {
    // The mean's uncertainty along gravity (the only direction |f| sees to first order).
    const Eigen::Vector3d u = s.accel_m_s2.normalized();
    prob.sigma.push_back(std::sqrt(u.cwiseAbs2().dot(s.accel_sigma_m_s2.cwiseAbs2())));
  }
  // Levenberg-Marquardt from zero (Marquardt's scaling of the damping by diag(J^T J)).
  Vec p = Vec::Zero(np), r, r_try;
  Mat J;
  prob.evaluate(p, r, &J);
  double cost = r.squaredNorm(), lambda = 1e-3;
  std::size_t it = 0;
  for (; it < 200; ++it) {
    const Mat A = J.transpose() * J;
    const Vec grad = J.transpose() * r;
    Mat damped = A;
    damped.diagonal() += lambda * A.diagonal();
    const Vec step = damped.ldlt().solve(-grad);
    if (!step.allFinite()) break;
    const Vec trial = p + step;
    prob.evaluate(trial, r_try, nullptr);
    const double c = r_try.squaredNorm();
    if (c < cost) {
      p = trial;
      const bool converged = cost - c <= 1e-15 * cost || step.cwiseAbs().maxCoeff() < 1e-13;
      cost = c;
      lambda = std::max(lambda * 0.1, 1e-12);
      prob.evaluate(p, r, &J);
      if (converged) break;
    } else {
      lambda *= 10.0;
      if (lambda > 1e12) break;
    }
  }
  if (!p.allFinite()) {
    why = "the least-squares fit did not converge";
    return false;
  }
  fit.iterations = it + 1;
  fit.segments = segments.size();
  fit.parameters = static_cast<std::size_t>(np);
  fit.dof = fit.segments > fit.parameters ? fit.segments - fit.parameters : 0;
  fit.chi2 = cost;
  // Covariance: the weights' own (J^T W J)^-1, scaled up by the residual's
  // variance per degree of freedom when that is larger (the weights come
  // from the noise models; the residual also sees what they miss).
  const Mat info = J.transpose() * J;
  Mat cov = info.inverse();
  if (fit.dof > 0) cov *= std::max(1.0, cost / static_cast<double>(fit.dof));
  fit.gravity_m_s2 = prob.g;
  fit.gravity_relative_sigma = gravity.relative_sigma();
  fit.accel_bias_m_s2 = p.head<3>();
  fit.accel_scale_ppm = p.segment<3>(3) * 1e6;
  fit.accel_misalign_rad = cross_axis(p);
  for (Eigen::Index i = 0; i < 3; ++i) {
    fit.accel_bias_sigma_m_s2[i] = std::sqrt(cov(i, i));
    // A common scale error is g's: its uncertainty adds to every axis.
    fit.accel_scale_sigma_ppm[i] = 1e6 * std::sqrt(cov(3 + i, 3 + i) + std::pow(fit.gravity_relative_sigma, 2));
  }
  if (fit.misalign_fitted) {
    for (std::size_t q = 0; q < 3; ++q) {
      const auto [i, j] = kPairs[q];
      const auto c = static_cast<Eigen::Index>(6 + q);
      fit.accel_misalign_sigma_rad(i, j) = fit.accel_misalign_sigma_rad(j, i) = std::sqrt(cov(c, c));
    }
  }
  // Residuals in m/s^2, and the gyro bias with the calibrated up directions.
  const Eigen::Matrix3d K = fit.correction();
  const double omega_up = est::wgs84::kOmegaIe * std::sin(gravity.latitude_deg * kDeg);
  std::vector<Eigen::Vector3d> rate;
  double ss = 0.0;
  for (const SegmentMean& s : segments) {
    const Eigen::Vector3d y = K * (s.accel_m_s2 - fit.accel_bias_m_s2);
    fit.residuals_m_s2.push_back(y.norm() - prob.g);
    ss += fit.residuals_m_s2.back() * fit.residuals_m_s2.back();
    // Earth rate's vertical part (NED: -Omega sin(lat) along down) is +Omega sin(lat) along up.
    rate.push_back(s.gyro_rad_s - omega_up * y.normalized());
  }
  fit.residual_rms_m_s2 = std::sqrt(ss / static_cast<double>(segments.size()));
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), var = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& w : rate) mean += w;
  mean /= static_cast<double>(rate.size());
  for (const Eigen::Vector3d& w : rate) var += (w - mean).cwiseAbs2();
  var /= static_cast<double>(rate.size() - 1);
  fit.gyro_bias_rad_s = mean;
  fit.gyro_bias_sigma_rad_s = (var / static_cast<double>(rate.size())).cwiseSqrt();
  return true;
}

void symmetric_form(const Eigen::Matrix3d& G, Eigen::Vector3d& scale_ppm, Eigen::Matrix3d& misalign_sym_rad) {
  const Eigen::Matrix3d P = G * G.transpose();
  Eigen::Vector3d d = P.diagonal().cwiseSqrt();
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
  for (int it = 0; it < 100; ++it) {
    const Eigen::Matrix3d Dinv = d.cwiseInverse().asDiagonal();
    A = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(Dinv * P * Dinv).operatorSqrt();
    const Eigen::Vector3d diag = A.diagonal();
    d = d.cwiseProduct(diag);
    if ((diag - Eigen::Vector3d::Ones()).cwiseAbs().maxCoeff() < 1e-15) break;
  }
  scale_ppm = (d - Eigen::Vector3d::Ones()) * 1e6;
  misalign_sym_rad = A - Eigen::Matrix3d::Identity();
  misalign_sym_rad.diagonal().setZero();
}

}  // namespace sinu::calibration
