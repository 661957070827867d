#pragma once
// Fits the OBA pairs of a window (oba_pair_builder.hpp): the attitude
// C = C_n0_b0 and the constant gyro and accelerometer biases b_g, b_a, with
// the first-order covariance of the attitude now, in fixed memory.
//
// Model (b0 axes, centred over the window, which removes the unknown
// initial velocity c): C^T beta_k = alpha_k + D_k b_g - A_k b_a + noise.
// 1. Start: Wahba's problem with zero biases, B = sum beta' alpha'^T =
//    U S V^T, C = U diag(1, 1, det U det V) V^T (proper rotation).
// 2. Gauss-Newton on x = (theta, b_g, b_a), C <- C exp([theta x]):
//    rho_k = C^T beta_k - alpha_k, J_k = [[a_k x], -D_k, A_k] with
//    a_k = alpha_k + D_k b_g - A_k b_a, weights W = R^-1 (horizontal
//    kappa sigma_v^2, vertical the height-slope variance), priors
//    b_g ~ N(m_g, P_g), b_a ~ N(0, s_a^2). A gyro bias tilts the
//    gyro-carried attitude by A b_g and bends alpha by D b_g: over gravity a
//    quadratic in time that the attitude terms (linear in time) cannot
//    absorb, so its horizontal part is estimated; an accelerometer bias is a
//    tilt unless the body rotates. One confusion matters: in a steady turn
//    (speed V, rate w) a roll-axis gyro bias and yaw give the same
//    quadratic, so yaw inherits about b g / (V w^2) (25 s x b at 45 m/s and
//    5.4 deg/s) until the turn rate changes.
// 3. Covariance (sandwich, so the correlated height-slope noise is exact):
//    P_x = N^-1 (sum J^T W R W J + heights + priors) N^-1, N = sum J^T W J + priors.
//    The gyro's white noise (random walk N_g sqrt(t) of the attitude) is a
//    consider term: over a window T, the LS fit of a Brownian motion by
//    b t + r t^2 / 2 has var b = 4.34 N^2 / T, var r = 15.24 N^2 / T^3,
//    cov = -7.05 N^2 / T^2 and leaves 0.105 N^2 T at the end point; the fit
//    absorbs the b part, the r part is propagated through D1 and A1.
// Every sum is a quadratic form in the pair vector u, so the solver keeps
// only sum u u^T and sum u; at a solve it factors the centred Gram
// G = Y Y^T and evaluates the sums over the columns of Y ("virtual pairs"):
// sum_k f(u_k') = sum_r f(Y_r) for every quadratic f, whatever C and W.
#include <Eigen/Core>

#include "estimator/align/oba_pair_builder.hpp"

namespace sinu::est {

struct ObaNoise {
  double horizontal_var_m2_s2 = 0.04;  // per pair, each horizontal axis
  double vertical_var_m2_s2 = 0.1;     // per pair (weighting only)
  double height_sigma_m = 1.0;         // white height error (with the height Gram)
  double accel_bias_sigma_m_s2 = 0.3;
  // Prior of the remaining gyro bias (what the integration has not removed).
  Eigen::Vector3d gyro_bias_prior_rad_s = Eigen::Vector3d::Zero();
  Eigen::Matrix3d gyro_bias_prior_cov_rad2_s2 = 1e-4 * Eigen::Matrix3d::Identity();
  double gyro_arw_rad_rt_s = 2.6e-4;   // gyro white noise density
};

/// The output instant: body-side sensitivities there and the window length.
struct ObaNow {
  Eigen::Matrix3d A_s = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d A1_s2 = Eigen::Matrix3d::Zero();
  double window_s = 0.0;
};

struct ObaFit {
  Eigen::Matrix3d C_n0b0 = Eigen::Matrix3d::Identity();
  Eigen::Vector3d gyro_bias_rad_s = Eigen::Vector3d::Zero();  // body axes, measured - true
  /// Error e of the attitude now, b0 axes: C_n0_b_hat = exp([e x]) C_n0_b, for
  /// C_n0_b_hat = C_n0_b0 exp(-[A_now b_g x]) C_b0_b_gyro.
  Eigen::Matrix3d P_att_b0_rad2 = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d P_gyro_bias_rad2_s2 = Eigen::Matrix3d::Zero();
  bool has_null = false;  // a direction without information (pseudo-inverse used)
};

class ObaSolver {
 public:
  void reset();
  void add(const ObaVector& u);
  long count() const { return n_; }
  ObaVector mean() const { return n_ > 0 ? ObaVector(sum_u_ / static_cast<double>(n_)) : ObaVector::Zero(); }
  /// Needs 2 pairs. height_gram: ObaPairBuilder::height_noise_gram(mean());
  /// down_n0: the current down axis in n0.
  bool solve(const ObaGram& height_gram, const Eigen::Vector3d& down_n0, const ObaNoise& noise, const ObaNow& now,
             ObaFit& out) const;
  /// Re-expresses the pairs after `delta` more gyro bias is removed.
  void correct_gyro_bias(const Eigen::Vector3d& delta_rad_s);

 private:
  long n_ = 0;
  ObaVector sum_u_ = ObaVector::Zero();
  ObaGram sum_uu_ = ObaGram::Zero();
};

}  // namespace sinu::est
