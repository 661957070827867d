#pragma once
// The unit's yaw on a ground vehicle beyond what the vehicle detector found
// [rad]: the non-holonomic constraint's lateral axis turns with it. Found
// from the body velocity, the bracket's yaw carries the heading's error of
// that moment; as a state (started correlated with that heading error,
// ErrorStateFilter::start_vehicle_mount) the GNSS motion, which sees the
// heading, separates the two. Switched on when the detector finds a unit on
// a bracket; a property of the installation, not of the sensor.
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct VehicleMount {
  static constexpr EffectSpec spec{Effect::VehicleMount, "vehicle_mount", Components::One, "deg", kRadToDeg, 0.1,
                                   0.0, false, 3.2, Triad::None, Triad::None, Needs::Nothing, nullptr, 0.0};
  /// The lateral row: (lateral + m forward) . v_b for the unit turned m further, so d/dm = forward . v_b and
  /// the state (true - estimate) enters with the opposite sign; the axes used are turned by the estimate.
  template <class T> static void nonholonomic(EffectView v, T& t) {
    t.axes = t.axes.turned(v.scalar());
    if (t.slice.active()) t.H(0, t.slice.start) = -t.axes.forward_b().dot(t.v_b);
  }
};

}  // namespace sinu::est::effects
