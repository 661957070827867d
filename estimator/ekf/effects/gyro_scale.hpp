#pragma once
// The gyro's scale-factor error, per axis:   w = (1 - s) w   [-, shown in ppm]
// Shows in turns: a 1 % error is 3.6 deg per full turn.
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct GyroScale {
  static constexpr EffectSpec spec{Effect::GyroScale, "gyro_scale", Components::Xyz, "ppm", 1e6, 0.02, 1e-6, true,
                                   0.035, Triad::Gyro, Triad::Gyro};
  static constexpr ImuStage stage = ImuStage::Scale;
  template <class S> static void correct(EffectView v, S& s) {
    s.gyro = (Eigen::Vector3d::Ones() - v.vec3()).cwiseProduct(s.gyro);
  }
  template <class T> static void couple(EffectView, T& t) {
    t.add_attitude(0, -1.0 * t.C * t.w_b.asDiagonal() * t.dt);
  }
};

}  // namespace sinu::est::effects
