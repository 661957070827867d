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
#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ekf/measurement_update.hpp"
#include "estimator/ekf/vehicle_axes.hpp"

namespace sinu::est {

struct NonholonomicConfig {
  double lateral_sigma_m_s = 0.1;
  double vertical_sigma_m_s = 0.1;
  double sigma_per_yaw_rate_m = 1.5;  // [m/s per rad/s]: an IMU 1.5 m from the rear axle
};

/// The vehicle's axes the constraint uses: the detector's (`found`) turned by
/// the effects that turn them (vehicle_mount: the bracket's yaw estimate).
VehicleAxes vehicle_axes_in_use(const ErrorStateFilter& filter, const VehicleAxes& found);

Measurement nonholonomic_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                     const Eigen::Vector3d& angular_rate_b_rad_s, const NonholonomicConfig& cfg,
                                     double gate_sigma, const VehicleAxes& axes = {});

}  // namespace sinu::est
