#include "estimator/align/oba_solver.hpp"

#include <algorithm>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "estimator/ins/rotation.hpp"

namespace sinu::est {

namespace {

using Vector9d = Eigen::Matrix<double, 9, 1>;
using Matrix9d = Eigen::Matrix<double, 9, 9>;
using Matrix39 = Eigen::Matrix<double, 3, 9>;
using Matrix96 = Eigen::Matrix<double, 9, 6>;
constexpr int kIterations = 3;         // Gauss-Newton steps from the Wahba start
constexpr double kNullRatio = 1e-12;  // scaled eigenvalue below this x the largest: no information
// Damping of the attitude steps (information of a 1 rad sigma): a direction
// without information (yaw in straight flight) keeps its Wahba value instead
// of jumping by radians; an observable (sigma < 3 deg) step changes < 0.3 %.
constexpr double kStepDamping = 1.0;

/// Y with G = Y Y^T (G symmetric positive semi-definite; rounding negatives dropped).
ObaGram square_root(const ObaGram& G) {
  const Eigen::SelfAdjointEigenSolver<ObaGram> eig(G);
  return eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
}

/// d rho / d (theta, b_g, b_a) of one (virtual) pair at the biases in x.
Matrix39 jacobian(const ObaVector& u, const Vector9d& x) {
  const Eigen::Matrix3d D = pair_D(u), A = pair_A(u);
  Matrix39 J;
  J << skew(pair_alpha(u) + D * x.segment<3>(3) - A * x.segment<3>(6)), -D, A;
  return J;
}

/// Pseudo-inverse after scaling the diagonal to 1 (the blocks have different
/// units); true when a direction has no information.
bool pseudo_inverse(const Matrix9d& N, Matrix9d& N_inv) {
  const Vector9d s = N.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::SelfAdjointEigenSolver<Matrix9d> eig(s.asDiagonal() * N * s.asDiagonal());
  const Vector9d lambda = eig.eigenvalues();
  Vector9d inv = Vector9d::Zero();
  bool has_null = false;
  for (Eigen::Index i = 0; i < 9; ++i) {
    if (lambda(i) > kNullRatio * lambda(8)) {
      inv(i) = 1.0 / lambda(i);
    } else {
      has_null = true;
    }
  }
  N_inv = s.asDiagonal() * eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose() * s.asDiagonal();
  return has_null;
}

}  // namespace

void ObaSolver::reset() {
  n_ = 0;
  sum_u_.setZero();
  sum_uu_.setZero();
}

void ObaSolver::add(const ObaVector& u) {
  ++n_;
  sum_u_ += u;
  sum_uu_ += u * u.transpose();
}

void ObaSolver::correct_gyro_bias(const Eigen::Vector3d& delta) {
  const ObaGram T = gyro_correction_map(delta);
  sum_u_ = T * sum_u_;
  sum_uu_ = T * sum_uu_ * T.transpose();
}

bool ObaSolver::solve(const ObaGram& height_gram, const Eigen::Vector3d& down_n0, const ObaNoise& noise,
                      const ObaNow& now, ObaFit& out) const {
  if (n_ < 2) return false;
  const ObaGram Y = square_root(sum_uu_ - sum_u_ * sum_u_.transpose() / static_cast<double>(n_));

  // 1. Wahba start: SVD of B = sum beta' alpha'^T, det-corrected.
  Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
  for (Eigen::Index r = 0; r < kObaPairSize; ++r) B += pair_beta(Y.col(r)) * pair_alpha(Y.col(r)).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(B, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const double det = svd.matrixU().determinant() * svd.matrixV().determinant();
  Eigen::Matrix3d C = svd.matrixU() * Eigen::Vector3d(1.0, 1.0, det < 0.0 ? -1.0 : 1.0).asDiagonal() *
                      svd.matrixV().transpose();

  // 2. Gauss-Newton (damped steps); the weights follow the current down axis in b0.
  const double h = noise.horizontal_var_m2_s2, v = noise.vertical_var_m2_s2;
  Matrix9d prior = Matrix9d::Zero();  // information; prior N(m, P0) adds P0^-1 and P0^-1 m
  prior.block<3, 3>(3, 3) = noise.gyro_bias_prior_cov_rad2_s2.inverse();
  prior.block<3, 3>(6, 6) = Eigen::Matrix3d::Identity() / (noise.accel_bias_sigma_m_s2 * noise.accel_bias_sigma_m_s2);
  Vector9d x = Vector9d::Zero(), prior_rhs = Vector9d::Zero();
  prior_rhs.segment<3>(3) = prior.block<3, 3>(3, 3) * noise.gyro_bias_prior_rad_s;
  Matrix9d N, N_inv;
  Eigen::Vector3d z;
  Eigen::Matrix3d W;
  for (int iter = 0; iter <= kIterations; ++iter) {
    z = C.transpose() * down_n0;
    W = Eigen::Matrix3d::Identity() / h + (1.0 / v - 1.0 / h) * z * z.transpose();
    N = prior;
    Vector9d g = Vector9d::Zero();
    for (Eigen::Index r = 0; r < kObaPairSize; ++r) {
      const ObaVector y = Y.col(r);
      const Matrix39 J = jacobian(y, x);
      N += J.transpose() * W * J;
      g += J.transpose() * W * (C.transpose() * pair_beta(y) - pair_alpha(y));
    }
    out.has_null = pseudo_inverse(N, N_inv);
    if (iter == kIterations) break;  // the last pass only linearises at the solution
    Matrix9d N_step = N, N_step_inv;
    N_step.topLeftCorner<3, 3>() += kStepDamping * Eigen::Matrix3d::Identity();
    pseudo_inverse(N_step, N_step_inv);
    x = N_step_inv * (prior_rhs - g);
    C = C * quat_from_rotation_vector(x.head<3>()).toRotationMatrix();
  }

  // 3. Sandwich: horizontal white noise (W R W = (I - z z^T) / h), heights
  // through the exact height Gram (W z = z / v), priors; and the response
  // to the random-walk consider terms (b, r): residuals move by D b + D1 r.
  Matrix9d S = prior;
  Matrix96 G = Matrix96::Zero();
  const Eigen::Matrix3d horizontal = (Eigen::Matrix3d::Identity() - z * z.transpose()) / h;
  for (Eigen::Index r = 0; r < kObaPairSize; ++r) {
    const ObaVector y = Y.col(r);
    const Matrix39 J = jacobian(y, x);
    S += J.transpose() * horizontal * J;
    G.leftCols<3>() += J.transpose() * W * pair_D(y);
    G.rightCols<3>() += J.transpose() * W * pair_D1(y);
  }
  const ObaGram Yh = square_root(height_gram);
  for (Eigen::Index r = 0; r < kObaPairSize; ++r) {
    const Vector9d w = jacobian(Yh.col(r), x).transpose() * z / v;
    S += noise.height_sigma_m * noise.height_sigma_m * w * w.transpose();
  }
  const Matrix9d P_x = N_inv * S * N_inv;

  // Attitude now: e = theta - A_now (b_g error) + (true random-walk attitude).
  Matrix39 T;
  T << Eigen::Matrix3d::Identity(), -now.A_s, Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, 6> L = -T * N_inv * G;  // per (b, r) of the random walk
  L.leftCols<3>() += now.A_s;
  L.rightCols<3>() += now.A1_s2;
  const double n2 = noise.gyro_arw_rad_rt_s * noise.gyro_arw_rad_rt_s, tw = std::max(now.window_s, 1e-3);
  Eigen::Matrix<double, 6, 6> Q;
  Q << 4.34 / tw * Eigen::Matrix3d::Identity(), -7.05 / (tw * tw) * Eigen::Matrix3d::Identity(),
      -7.05 / (tw * tw) * Eigen::Matrix3d::Identity(), 15.24 / (tw * tw * tw) * Eigen::Matrix3d::Identity();
  Q *= n2;
  const Eigen::Matrix<double, 3, 6> Lb = -(N_inv * G).middleRows<3>(3);
  out.P_att_b0_rad2 = T * P_x * T.transpose() + L * Q * L.transpose() + 0.105 * n2 * tw * Eigen::Matrix3d::Identity();
  out.P_gyro_bias_rad2_s2 = P_x.block<3, 3>(3, 3) + Lb * Q * Lb.transpose();
  out.C_n0b0 = C;
  out.gyro_bias_rad_s = x.segment<3>(3);
  return true;
}

}  // namespace sinu::est
