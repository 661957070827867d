#pragma once
// Small rotation helpers: skew matrix, rotation-vector quaternion, ZYX Euler.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sinu::est {

/// [v x]: skew(v) * w == v.cross(w).
Eigen::Matrix3d skew(const Eigen::Vector3d& v);

/// Quaternion of the rotation vector `rot_rad` (exact, safe near zero).
Eigen::Quaterniond quat_from_rotation_vector(const Eigen::Vector3d& rot_rad);

/// q_nb from ZYX Euler angles (roll, pitch, yaw) [rad] of body w.r.t. NED.
Eigen::Quaterniond quat_from_euler(double roll_rad, double pitch_rad, double yaw_rad);

/// (roll, pitch, yaw) [rad] of q_nb; yaw in (-pi, pi].
Eigen::Vector3d euler_from_quat(const Eigen::Quaterniond& q_nb);

/// Wraps an angle to (-pi, pi].
double wrap_pi(double angle_rad);

}  // namespace sinu::est
