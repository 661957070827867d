#pragma once
// The NavSolution's covariance in the forms external consumers ask for:
// Euler angles instead of the EKF's small-angle attitude error, body-frame
// velocity, and 1-sigma accuracies. First-order (Jacobian) propagation.
//
// The EKF's error convention (estimator/ekf/error_state_filter.cpp, feedback):
// position and velocity errors are estimate - truth (NED metres, m/s); the
// attitude error phi is truth relative to estimate, C_nb_hat = (I - [phi x]) C_nb
// (NED, radians). Every output below is estimate - truth, so its cross terms
// with position keep their sign.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "firmware/board/nav_solution.hpp"

namespace sinu::board {

/// Roll, pitch, yaw [rad] of body FRD in NED, the aerospace ZYX sequence
/// (C_nb = Rz(yaw) Ry(pitch) Rx(roll)); yaw in (-pi, pi].
Eigen::Vector3d roll_pitch_yaw_rad(const Eigen::Quaterniond& q_nb);

/// Covariance of (north, east, down [m], roll, pitch, yaw [rad]).
/// With e = (roll, pitch, yaw), a change of e turns the body by
/// E de (NED), E = [x_roll, y_pitch, z_yaw] the Euler axes in NED
/// (x_roll = C_nb e_x, y_pitch = Rz(yaw) e_y, z_yaw = e_z), so the Euler error
/// is de = -E^-1 phi. E is singular at pitch +-90 deg: the Jacobian uses the
/// pitch clamped to +-89.9 deg (yaw and roll variances then grow large, as
/// they should, instead of becoming infinite).
Eigen::Matrix<double, 6, 6> pose_covariance(const NavSolution& sol);

/// Covariance of the body-frame velocity v_b = C_bn v_n [m^2/s^2]:
/// dv_b = C_bn (dv_n - [v_n x] phi), so a heading error at speed shows as
/// a lateral velocity error.
Eigen::Matrix3d body_velocity_covariance(const NavSolution& sol);

/// 1-sigma horizontal position error along its worst direction [m]
/// (square root of the larger eigenvalue of the north-east covariance).
double horizontal_sigma_m(const NavSolution& sol);
/// 1-sigma vertical position error [m].
double vertical_sigma_m(const NavSolution& sol);
/// 1-sigma velocity error along its worst direction [m/s] (3-D).
double velocity_sigma_m_s(const NavSolution& sol);

}  // namespace sinu::board
