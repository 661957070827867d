#include "estimator/align/oba_body_integrals.hpp"

#include "estimator/ins/rotation.hpp"

namespace sinu::est {

void ObaBodyIntegrals::reset() {
  q_b0b_.setIdentity();
  C_b0b_.setIdentity();
  alpha_m_s_.setZero();
  A_s_.setZero();
  D_m_.setZero();
  A1_s2_.setZero();
  D1_m_s_.setZero();
  elapsed_s_ = 0.0;
}

void ObaBodyIntegrals::step(const ImuSample& prev, const ImuSample& cur, double T) {
  // Attitude: rotation vector of linear rates over the interval (with coning).
  const Eigen::Vector3d& w0 = prev.angular_rate_b_rad_s;
  const Eigen::Vector3d& w1 = cur.angular_rate_b_rad_s;
  const Eigen::Vector3d dtheta_rad = 0.5 * (w0 + w1) * T + w0.cross(w1) * (T * T / 12.0);
  q_b0b_ = (q_b0b_ * quat_from_rotation_vector(dtheta_rad)).normalized();
  const Eigen::Matrix3d C_old = C_b0b_;
  C_b0b_ = q_b0b_.toRotationMatrix();

  // alpha: trapezoid of the specific force resolved in b0.
  const Eigen::Vector3d u0_m_s2 = C_old * prev.specific_force_b_m_s2;
  const Eigen::Vector3d u1_m_s2 = C_b0b_ * cur.specific_force_b_m_s2;
  alpha_m_s_ += 0.5 * T * (u0_m_s2 + u1_m_s2);

  // Sensitivities: A = int C_b0_b, D = int [u x] A, A1 = int C_b0_b tau,
  // D1 = int [u x] A1 (all trapezoidal).
  const Eigen::Matrix3d A_old = A_s_, A1_old = A1_s2_;
  const Eigen::Matrix3d u0x = skew(u0_m_s2), u1x = skew(u1_m_s2);
  A_s_ += 0.5 * T * (C_old + C_b0b_);
  D_m_ += 0.5 * T * (u0x * A_old + u1x * A_s_);
  A1_s2_ += 0.5 * T * (C_old * elapsed_s_ + C_b0b_ * (elapsed_s_ + T));
  D1_m_s_ += 0.5 * T * (u0x * A1_old + u1x * A1_s2_);
  elapsed_s_ += T;
}

void ObaBodyIntegrals::correct_gyro_bias(const Eigen::Vector3d& delta) {
  q_b0b_ = (quat_from_rotation_vector(-A_s_ * delta) * q_b0b_).normalized();
  C_b0b_ = q_b0b_.toRotationMatrix();
  alpha_m_s_ += D_m_ * delta;
}

}  // namespace sinu::est
