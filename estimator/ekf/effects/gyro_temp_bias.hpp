#pragma once
// The gyro bias's temperature coefficient:   w = w_raw - b - k (T - T_ref)
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct GyroTempBias {
  static constexpr EffectSpec spec{Effect::GyroTempBias, "gyro_temp_bias", Components::Xyz, "deg/s/degC", kRadToDeg,
                                   1e-3, 1e-8, true, 2e-3, Triad::Gyro, Triad::None, Needs::Temperature};
  static constexpr ImuStage stage = ImuStage::Offset;
  template <class S> static void correct(EffectView v, S& s) { s.gyro_temp_offset += v.vec3() * s.dT; }
  template <class T> static void couple(EffectView, T& t) {
    t.add_attitude(0, -1.0 * t.C * Eigen::Vector3d::Constant(t.dT).asDiagonal() * t.dt);
  }
};

}  // namespace sinu::est::effects
