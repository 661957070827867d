#include "firmware/board/outputs/nav_uncertainty.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace sinu::board {

namespace {

constexpr double kMaxJacobianPitchRad = 89.9 * std::numbers::pi / 180.0;

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

/// Euler-angle change -> rotation vector in NED (columns: the roll, pitch and yaw axes).
Eigen::Matrix3d euler_axes_ned(double pitch_rad, double yaw_rad) {
  const double cp = std::cos(pitch_rad), sp = std::sin(pitch_rad);
  const double cy = std::cos(yaw_rad), sy = std::sin(yaw_rad);
  Eigen::Matrix3d E;
  E << cy * cp, -sy, 0.0,
       sy * cp, cy, 0.0,
       -sp, 0.0, 1.0;
  return E;
}

}  // namespace

Eigen::Vector3d roll_pitch_yaw_rad(const Eigen::Quaterniond& q_nb) {
  const Eigen::Quaterniond q = q_nb.normalized();
  const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
  const double roll = std::atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y));
  const double pitch = std::asin(std::clamp(2.0 * (w * y - z * x), -1.0, 1.0));
  const double yaw = std::atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z));
  return {roll, pitch, yaw};
}

Eigen::Matrix<double, 6, 6> pose_covariance(const NavSolution& sol) {
  const Eigen::Vector3d rpy = roll_pitch_yaw_rad(sol.q_nb);
  const double pitch = std::clamp(rpy.y(), -kMaxJacobianPitchRad, kMaxJacobianPitchRad);
  Eigen::Matrix<double, 6, 9> J = Eigen::Matrix<double, 6, 9>::Zero();
  J.block<3, 3>(0, 0).setIdentity();
  J.block<3, 3>(3, 6) = -euler_axes_ned(pitch, rpy.z()).inverse();
  return J * sol.P_nav * J.transpose();
}

Eigen::Matrix3d body_velocity_covariance(const NavSolution& sol) {
  const Eigen::Matrix3d C_bn = sol.q_nb.normalized().toRotationMatrix().transpose();
  Eigen::Matrix<double, 3, 9> J = Eigen::Matrix<double, 3, 9>::Zero();
  J.block<3, 3>(0, 3) = C_bn;
  J.block<3, 3>(0, 6) = -C_bn * skew(sol.v_ned_m_s);
  return J * sol.P_nav * J.transpose();
}

double horizontal_sigma_m(const NavSolution& sol) {
  const double a = sol.P_nav(0, 0), b = 0.5 * (sol.P_nav(0, 1) + sol.P_nav(1, 0)), c = sol.P_nav(1, 1);
  const double largest = 0.5 * (a + c) + std::hypot(0.5 * (a - c), b);  // 2x2 symmetric, closed form
  return std::sqrt(std::max(largest, 0.0));
}

double vertical_sigma_m(const NavSolution& sol) { return std::sqrt(std::max(sol.P_nav(2, 2), 0.0)); }

double velocity_sigma_m_s(const NavSolution& sol) {
  const Eigen::Matrix3d Pv = sol.P_nav.block<3, 3>(3, 3);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(0.5 * (Pv + Pv.transpose()), Eigen::EigenvaluesOnly);  // closed form, no allocation
  return std::sqrt(std::max(eig.eigenvalues().maxCoeff(), 0.0));
}

}  // namespace sinu::board
