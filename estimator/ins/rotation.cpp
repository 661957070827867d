#include "estimator/ins/rotation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sinu::est {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(),  //
      v.z(), 0.0, -v.x(),   //
      -v.y(), v.x(), 0.0;
  return m;
}

Eigen::Quaterniond quat_from_rotation_vector(const Eigen::Vector3d& rot) {
  const double angle = rot.norm();
  const double half = 0.5 * angle;
  // sin(x/2)/x by its Taylor series below 1e-4 rad (error < 1e-17).
  const double k = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(half) / angle;
  return Eigen::Quaterniond(std::cos(half), k * rot.x(), k * rot.y(), k * rot.z());
}

Eigen::Quaterniond quat_from_euler(double roll, double pitch, double yaw) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()));
}

Eigen::Vector3d euler_from_quat(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d c = q.toRotationMatrix();
  const double pitch = std::asin(std::clamp(-c(2, 0), -1.0, 1.0));
  const double roll = std::atan2(c(2, 1), c(2, 2));
  const double yaw = std::atan2(c(1, 0), c(0, 0));
  return {roll, pitch, yaw};
}

double wrap_pi(double a) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  a = std::fmod(a + std::numbers::pi, kTwoPi);
  if (a <= 0.0) a += kTwoPi;
  return a - std::numbers::pi;
}

}  // namespace sinu::est
