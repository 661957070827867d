#pragma once
// The gyro's turn-on bias (see accel_bias.hpp).   w = w_raw - b - ...  [rad/s]
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct GyroBias {
  // ICM-20948 class: up to 0.6 deg/s
  static constexpr EffectSpec spec{Effect::GyroBias, "gyro_bias", Components::Xyz, "deg/s", kRadToDeg, 0.01, 2e-6,
                                   false, 0.2, Triad::Gyro};
  static constexpr ImuStage stage = ImuStage::Offset;
  template <class S> static void correct(EffectView v, S& s) { s.gyro_offset += v.vec3(); }
  template <class T> static void couple(EffectView, T& t) {
    t.add_attitude(0, -1.0 * t.C * Eigen::Vector3d::Ones().asDiagonal() * t.dt);
  }
  template <class T> static void process_noise(EffectView, T& t) { t.walk(t.noise.gyro_bias_walk); }
};

}  // namespace sinu::est::effects
