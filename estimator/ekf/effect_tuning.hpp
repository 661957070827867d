#pragma once
// Initial uncertainty and random-walk process noise of the optional effect
// states. Magnitudes chosen to cover consumer MEMS and the simulator's
// "large enough to matter" draws (scale errors of percent, lever arms of a
// metre, latencies of a few hundred milliseconds).
#include <array>

#include "estimator/ekf/state_layout.hpp"

namespace sinu::est {

struct EffectTuning {
  // per effect: initial sigma [state unit] and random-walk density [unit/sqrt(s)]
  std::array<double, kEffectCount> initial_sigma = {
      0.02,    // accel_scale [-] (20000 ppm)
      0.02,    // gyro_scale [-]
      1.0,     // lever_arm [m]
      0.1,     // gps_latency [s] (serial NMEA: 0.02-0.2 s after the fix)
      0.01,    // accel_temp_bias [m/s^2/degC]
      1e-3,    // gyro_temp_bias [rad/s/degC]
      0.1,     // accel_bias [m/s^2] (ICM-20948 class: +-0.06..0.2 turn-on)
      0.01,    // gyro_bias [rad/s] (0.6 deg/s)
      1.5,     // gps_position_bias [m] (until the first fix: then from its sigma, below)
      5.0,     // mag_earth_field [uT] (set from the attitude at mag start-up)
      30.0,    // mag_hard_iron [uT] (a nearby motor or battery: tens of uT)
      0.2,     // mag_soft_iron [-] (steel nearby: up to ~20 %)
  };
  // accel/gyro bias walks: the rate random walk of the simulator's default unit
  // gps_position_bias is a GM process (below), not a random walk; the Earth
  // field changes by ~0.1 uT over 100 km; hard iron by a motor current change.
  std::array<double, kEffectCount> random_walk = {1e-6, 1e-6, 0.0, 1e-4, 1e-7, 1e-8, 2e-5, 2e-6, 0.0, 1e-3, 1e-2, 0.0};
  // gps_position_bias: the receiver's correlated error. Most of a receiver's
  // stated error (GST, or HDOP x UERE) is slow (atmosphere, multipath, orbits:
  // minutes), the rest white: the fix's variance is split, this fraction into
  // the GM states, whatever the receiver (metres standalone, centimetres RTK).
  double gps_bias_variance_fraction = 0.9;
  double gps_bias_tau_s = 120.0;
  double sigma(Effect e) const { return initial_sigma[static_cast<std::size_t>(e)]; }
  double walk(Effect e) const { return random_walk[static_cast<std::size_t>(e)]; }
};

}  // namespace sinu::est
