#pragma once
// The accelerometer's scale-factor error, per axis:   f = (1 - s) f   [-, shown in ppm]
// A scale error moves each axis by its own reading, so it shows in
// accelerations (and, on z, is a bias while level).
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct AccelScale {
  // ICM-20948: +-1.5 %; the simulator draws up to 3 %
  static constexpr EffectSpec spec{Effect::AccelScale, "accel_scale", Components::Xyz, "ppm", 1e6, 0.02, 1e-6, true,
                                   0.035, Triad::Accel, Triad::Accel};
  static constexpr ImuStage stage = ImuStage::Scale;
  template <class S> static void correct(EffectView v, S& s) {
    s.accel = (Eigen::Vector3d::Ones() - v.vec3()).cwiseProduct(s.accel);
  }
  template <class T> static void couple(EffectView, T& t) {
    t.add_velocity(0, 1.0 * t.C * t.f_b.asDiagonal() * t.dt);
  }
};

}  // namespace sinu::est::effects
