#pragma once
// How much older the GNSS velocity is than the fix's position [s]. A receiver
// whose velocity is averaged over the epoch interval, or differenced from
// consecutive positions, reports the motion of the interval's middle: half a
// fix period late (0.125 s at 4 Hz), while its position is of the epoch. The
// predicted velocity goes back by it along the mean acceleration over it:
// v - a tau (the navigator's velocity history gives a).
// Found on a real car (drive_0708: its RTK positions' NIS 4.4 -> 0.16 with
// the velocity moved 0.125 s; docs/diagnose.md).
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct GpsVelocityLatency {
  // 0 for a Doppler velocity of the epoch; a period's half for an averaged one
  static constexpr EffectSpec spec{Effect::GpsVelocityLatency, "gps_velocity_latency", Components::One, "s", 1.0,
                                   0.1, 0.0, true, 0.5, Triad::None, Triad::None, Needs::Nothing,
                                   "speed changes and turns (the acceleration the velocity lags)"};
  /// Horizontal rows: the velocity at its own time of validity, tau before the position's.
  template <class T> static void gnss_velocity(EffectView v, T& t) {
    t.antenna_velocity_n -= t.lag_accel_n * v.scalar();
    if (t.slice.active()) t.H.block(0, t.slice.start, 2, 1) = t.lag_accel_n.template head<2>();
  }
};

}  // namespace sinu::est::effects
