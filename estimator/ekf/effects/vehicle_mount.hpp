#pragma once
// The unit's yaw on a ground vehicle beyond what the vehicle detector found
// [rad]: the non-holonomic constraint's lateral axis turns with it. Found
// from the body velocity, the bracket's yaw carries the heading's error of
// that moment; as a state (started correlated with that heading error,
// ErrorStateFilter::start_vehicle_mount) the GNSS motion, which sees the
// heading, separates the two. Switched on when the detector finds a unit on
// a bracket; a property of the installation, not of the sensor.
#include "estimator/ekf/effects/effect_spec.hpp"
#include "estimator/ekf/vehicle_axes.hpp"

namespace sinu::est::effects {

struct VehicleMount {
  static constexpr EffectSpec spec{Effect::VehicleMount, "vehicle_mount", Components::One, "deg", kRadToDeg, 0.1,
                                   0.0, false, 3.2, Triad::None, Triad::None, Needs::Nothing, nullptr, 0.0};
  /// The axes in use: the detector's, turned by the estimate.
  static void turn_vehicle_axes(EffectView v, VehicleAxes& axes) { axes = axes.turned(v.scalar()); }
  /// The lateral row: (lateral + m forward) . v_b for the unit turned m further, so d/dm = forward . v_b and
  /// the state (true - estimate) enters with the opposite sign.
  template <class T> static void nonholonomic(EffectView, T& t) {
    if (t.slice.active()) t.H(0, t.slice.start) = -t.axes.forward_b().dot(t.v_b);
  }
};

}  // namespace sinu::est::effects
