#pragma once
// The GNSS fix's latency [s]: a fix arriving at t was valid at t - latency.
// The navigator fuses each epoch at its time of validity (delayed horizon)
// with this estimate; its error moves the prediction by the motion over it:
// position by v, velocity by a.
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct GpsLatency {
  // serial NMEA: 0.02-0.2 s after the fix; a receiver's report up to ~0.3 s
  // Reported 25 ms from the configured value (--gps-latency): 1 m along the track at 40 m/s, a fix's own error
  static constexpr EffectSpec spec{Effect::GpsLatency, "gps_latency", Components::One, "s", 1.0, 0.1, 1e-4, true, 0.6,
                                   Triad::None, Triad::None, Needs::Nothing, nullptr, 0.025};
  template <class T> static void gnss_position(EffectView, T& t) {
    if (t.slice.active()) t.H.block(0, t.slice.start, 3, 1) = t.nav.v_n_m_s;
  }
  template <class T> static void gnss_velocity(EffectView, T& t) {
    if (t.slice.active()) t.H.block(0, t.slice.start, 2, 1) = t.accel_n.template head<2>();
  }
};

}  // namespace sinu::est::effects
