#pragma once
// The gyro's sensitivity to specific force (g-sensitivity), a full 3x3:
//   w = w - G f   (f the compensated specific force) [rad/s per m/s^2, shown in deg/s/g]
// MEMS gyros: 0.01-0.2 deg/s per g.
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct GyroGSensitivity {
  // Prior 2e-4 rad/s per m/s^2 = 0.11 deg/s/g, a consumer MEMS gyro's typical datasheet figure (0.1
  // deg/s/g): at 0.28 deg/s/g the candidate paid for a spread no real unit has, and was named in 0 of 10
  // simulated flights with 0.05-0.15 deg/s/g (2 of 10 now; clean and other-effect flights unchanged,
  // docs/diagnose.md). The plausible bound stays 0.5 deg/s/g.
  static constexpr EffectSpec spec{Effect::GyroGSensitivity, "gyro_g_sensitivity", Components::Matrix, "deg/s/g",
                                   kRadToDeg * 9.80665, 2e-4, 0.0, true, 9e-4, Triad::Gyro,
                                   Triad::Accel};
  static constexpr ImuStage stage = ImuStage::Coupling;
  template <class S> static void correct(EffectView v, S& s) { s.gyro = s.gyro - v.matrix() * s.accel; }
  template <class T> static void couple(EffectView, T& t) {
    for (Eigen::Index i = 0; i < 3; ++i)
      for (Eigen::Index j = 0; j < 3; ++j) t.add_attitude(3 * i + j, -(t.C.col(i) * (t.f_b(j) * t.dt)));
  }
};

}  // namespace sinu::est::effects
