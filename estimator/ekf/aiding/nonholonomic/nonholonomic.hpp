#pragma once
// Non-holonomic constraint for a ground vehicle: its wheels neither slide
// sideways nor leave the road, so the velocity in the body frame has no
// lateral (y; x for a unit mounted sideways: `lateral_axis`) and no vertical
// (z) component. Measurement z = 0 for
//   v_b = C_bn v_n, rows lateral_axis and z.
// With C_nb_hat = (I - [phi x]) C_nb and dv = v_hat - v:
//   v_b_hat = C_bn (v + dv) + C_bn [phi x] v = v_b + C_bn dv - C_bn [v x] phi, so
//   H_vel = C_bn (rows lateral_axis, z),  H_att = -C_bn [v x] (the same rows).
// The noise covers sideslip, body roll on springs, an IMU not quite on the
// vehicle's axes, and the lateral speed a turn gives an IMU ahead of the rear
// axle (sigma grows with the yaw rate).
#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ekf/measurement_update.hpp"

namespace sinu::est {

struct NonholonomicConfig {
  double lateral_sigma_m_s = 0.1;
  double vertical_sigma_m_s = 0.1;
  double sigma_per_yaw_rate_m = 1.5;  // [m/s per rad/s]: an IMU 1.5 m from the rear axle
};

Measurement nonholonomic_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                     const Eigen::Vector3d& angular_rate_b_rad_s, const NonholonomicConfig& cfg,
                                     double gate_sigma, Eigen::Index lateral_axis = 1);

}  // namespace sinu::est
