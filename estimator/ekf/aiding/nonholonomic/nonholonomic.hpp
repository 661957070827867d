#pragma once
// Non-holonomic constraint for a ground vehicle: its wheels neither slide
// sideways nor leave the road, so the velocity has no component along the
// vehicle's lateral and vertical axes. The contract mounts the unit with its
// x forward (those axes are body y and z); a bracket may turn or tilt it, and
// the vehicle detector then finds the axes in the body frame (VehicleAxes).
// Measurement z = 0 for
//   v_b = C_bn v_n,  rows a^T v_b for a = lateral_b, vertical_b.
// With C_nb_hat = (I - [phi x]) C_nb and dv = v_hat - v:
//   v_b_hat = C_bn (v + dv) + C_bn [phi x] v = v_b + C_bn dv - C_bn [v x] phi, so
//   H_vel = a^T C_bn,  H_att = -a^T C_bn [v x].
// The noise covers sideslip, body roll on springs, a mount not quite found,
// and the lateral speed a turn gives an IMU ahead of the rear axle (sigma
// grows with the yaw rate).
#include <algorithm>
#include <cmath>

#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ekf/measurement_update.hpp"

namespace sinu::est {

struct NonholonomicConfig {
  double lateral_sigma_m_s = 0.1;
  double vertical_sigma_m_s = 0.1;
  double sigma_per_yaw_rate_m = 1.5;  // [m/s per rad/s]: an IMU 1.5 m from the rear axle
};

/// The vehicle's lateral (right) and vertical (down) axes in the unit's body frame, unit vectors.
struct VehicleAxes {
  Eigen::Vector3d lateral_b = Eigen::Vector3d::UnitY();
  Eigen::Vector3d vertical_b = Eigen::Vector3d::UnitZ();
  /// The vehicle's forward axis in the body frame.
  Eigen::Vector3d forward_b() const { return lateral_b.cross(vertical_b); }
  /// The unit's roll, pitch and yaw on the vehicle [rad]: ZYX angles of the body w.r.t. the vehicle's
  /// forward-right-down axes (a unit turned 45 deg right on its bracket: yaw +45 deg).
  Eigen::Vector3d unit_euler_rad() const {
    const Eigen::Vector3d f = forward_b();
    return {std::atan2(vertical_b.y(), vertical_b.z()), -std::asin(std::clamp(vertical_b.x(), -1.0, 1.0)),
            std::atan2(lateral_b.x(), f.x())};
  }
};

Measurement nonholonomic_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                     const Eigen::Vector3d& angular_rate_b_rad_s, const NonholonomicConfig& cfg,
                                     double gate_sigma, const VehicleAxes& axes = {});

}  // namespace sinu::est
