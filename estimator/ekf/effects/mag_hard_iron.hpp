#pragma once
// The magnetometer's hard iron, body [uT]: a nearby motor or battery,
// m = S C_bn F + h. Tens of uT; re-anchored when the vehicle's own field changes
// (the navigator), always carried with the magnetometer.
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct MagHardIron {
  // Reported from 1 uT: it turns a heading 1.5-3 deg before the first turn (a 20-40 uT horizontal field)
  static constexpr EffectSpec spec{Effect::MagHardIron, "mag_hard_iron", Components::Xyz, "uT", 1.0, 30.0, 1e-2, false,
                                   500.0, Triad::None, Triad::None, Needs::Nothing, nullptr, 1.0};
  template <class T> static void magnetometer(EffectView, T& t) {
    if (t.slice.active()) t.H.block(0, t.slice.start, 3, 3) = -Eigen::Matrix3d::Identity();
  }
};

}  // namespace sinu::est::effects
