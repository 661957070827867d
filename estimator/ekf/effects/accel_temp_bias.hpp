#pragma once
// The accelerometer bias's temperature coefficient, per axis, about the
// reference temperature of the alignment:   f = f_raw - b - k (T - T_ref)
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct AccelTempBias {
  static constexpr EffectSpec spec{Effect::AccelTempBias, "accel_temp_bias", Components::Xyz, "m/s^2/degC", 1.0, 0.01,
                                   1e-7, true, 0.02, Triad::Accel, Triad::None, Needs::Temperature};
  static constexpr ImuStage stage = ImuStage::Offset;
  template <class S> static void correct(EffectView v, S& s) { s.accel_temp_offset += v.vec3() * s.dT; }
  template <class T> static void couple(EffectView, T& t) {
    t.add_velocity(0, 1.0 * t.C * Eigen::Vector3d::Constant(t.dT).asDiagonal() * t.dt);
  }
};

}  // namespace sinu::est::effects
