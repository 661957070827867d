#pragma once
// Zero-velocity update: while the vehicle stands still (the navigator's rest
// detector and a GNSS speed near zero agree), its velocity is zero:
//   z = 0 for v_n,  H_vel = I,  sigma a few mm/s (engine vibration).
// It holds the velocity, the tilt and the accelerometer bias at every stop,
// where GNSS alone lets a MEMS INS wander by its noise.
#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ekf/measurement_update.hpp"

namespace sinu::est {

Measurement zero_velocity_measurement(const ErrorStateFilter& filter, const NavState& nav, double sigma_m_s,
                                      double gate_sigma);

}  // namespace sinu::est
