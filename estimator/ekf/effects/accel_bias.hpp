#pragma once
// The accelerometer's turn-on bias (random constant per power-on, walking
// slowly): calib.json's GM/AR models are the zero-mean part of a static
// session's error, so a unit's per-power-on bias needs its own states.
//   f = f_raw - b - ...     [m/s^2]
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct AccelBias {
  // ICM-20948 class: +-0.06..0.2 m/s^2 (walk: the sensor model's when it has one)
  static constexpr EffectSpec spec{Effect::AccelBias, "accel_bias", Components::Xyz, "m/s^2", 1.0, 0.1, 2e-5, false,
                                   2.0, Triad::Accel};
  static constexpr ImuStage stage = ImuStage::Offset;
  template <class S> static void correct(EffectView v, S& s) { s.accel_offset += v.vec3(); }
  template <class T> static void couple(EffectView, T& t) {
    t.add_velocity(0, 1.0 * t.C * Eigen::Vector3d::Ones().asDiagonal() * t.dt);
  }
  template <class T> static void process_noise(EffectView, T& t) { t.walk(t.noise.accel_bias_walk); }
};

}  // namespace sinu::est::effects
