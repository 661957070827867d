#pragma once
// GNSS antenna position aiding. The state at the filter's time is taken back
// to the measurement's time of validity with its velocity, the lever arm is
// added, and y = h(x_hat) - z in NED metres.
//   H_pos = I, H_att = [(C_nb l) x], H_lever = -C_nb, H_latency = v_n.
// A fix without a height (GnssObservation::has_height) gives the north and
// east rows only.
#include "estimator/ekf/aiding/gnss_observation.hpp"
#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ekf/measurement_update.hpp"

namespace sinu::est {

/// dt_back_s = filter time - measurement time (>= 0, a fraction of an IMU interval).
Measurement gnss_position_measurement(const ErrorStateFilter& filter, const NavState& nav, double dt_back_s,
                                      const GnssObservation& z, double gate_sigma);

}  // namespace sinu::est
