#pragma once
// GNSS horizontal velocity aiding (RMC/VTG speed and course). Antenna
// velocity = v + C_nb (w_b x l); taken back to the time of validity with the
// mean acceleration; a velocity older than the fix (gps_velocity_latency)
// goes back further by the mean acceleration over that lag
// (velocity_lag_accel_n). y = h(x_hat) - z (north, east) [m/s].
//   H_vel = I(2x3), H_att = [(C (w x l)) x], H_lever = -C [w x], H_latency = a_n.
#include "estimator/ekf/aiding/gnss_observation.hpp"
#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ekf/measurement_update.hpp"

namespace sinu::est {

Measurement gnss_velocity_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                      const Eigen::Vector3d& angular_rate_b_rad_s,
                                      const Eigen::Vector3d& accel_n_m_s2,
                                      const Eigen::Vector3d& velocity_lag_accel_n_m_s2, double dt_back_s,
                                      const GnssObservation& z, double gate_sigma);

}  // namespace sinu::est
