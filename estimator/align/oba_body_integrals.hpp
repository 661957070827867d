#pragma once
// Body-side integrals of optimisation-based alignment (OBA), in the frame b0
// of the body at the window start (fixed in inertial space):
//   C_b0_b(t)                            attitude change from the gyros
//   alpha(t) = int C_b0_b f_b dtau        specific-force integral [m/s]
//   A(t)     = int C_b0_b dtau            [s]
//   D(t)     = int [(C_b0_b f_b) x] A dtau  [m]
//   A1(t)    = int C_b0_b (tau - t0) dtau  [s^2]
//   D1(t)    = int [(C_b0_b f_b) x] A1 dtau [m s]
// the first-order sensitivities to sensor errors (measured minus true):
//   gyro bias b_g + r (t - t0): C_b0_b_hat = (I + [psi x]) C_b0_b with
//                   psi = A b_g + A1 r, alpha_hat = alpha - D b_g - D1 r
//   accel bias b_a: alpha_hat = alpha + A b_a
// (the ramp r stands for the gyro's random walk, see oba_solver.hpp).
// Rates and specific force are linear over each IMU interval (as in the
// strapdown): the attitude step has the coning term, the integrals are
// trapezoidal.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "estimator/ins/imu_sample.hpp"

namespace sinu::est {

class ObaBodyIntegrals {
 public:
  /// Starts at the current instant: C_b0_b = I, integrals zero.
  void reset();
  /// One IMU interval of length dt_s from sample `prev` to sample `cur`.
  void step(const ImuSample& prev, const ImuSample& cur, double dt_s);
  /// The caller now removes `delta_rad_s` more gyro bias: the integrals so
  /// far take the values they would have had (first order: C_b0_b turns by
  /// -A delta, alpha moves by D delta), so the model stays linear in the
  /// remaining bias.
  void correct_gyro_bias(const Eigen::Vector3d& delta_rad_s);

  const Eigen::Quaterniond& q_b0b() const { return q_b0b_; }
  const Eigen::Matrix3d& C_b0b() const { return C_b0b_; }
  const Eigen::Vector3d& alpha_m_s() const { return alpha_m_s_; }
  const Eigen::Matrix3d& A_s() const { return A_s_; }
  const Eigen::Matrix3d& D_m() const { return D_m_; }
  const Eigen::Matrix3d& A1_s2() const { return A1_s2_; }
  const Eigen::Matrix3d& D1_m_s() const { return D1_m_s_; }

 private:
  Eigen::Quaterniond q_b0b_ = Eigen::Quaterniond::Identity();
  Eigen::Matrix3d C_b0b_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d alpha_m_s_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d A_s_ = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d D_m_ = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d A1_s2_ = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d D1_m_s_ = Eigen::Matrix3d::Zero();
  double elapsed_s_ = 0.0;
};

}  // namespace sinu::est
