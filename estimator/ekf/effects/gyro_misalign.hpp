#pragma once
// The gyro's cross-axis sensitivity (misalignment), off-diagonal:
//   w = (I - M) w,  M(i,j): axis i senses axis j   [rad, shown in mrad]
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct GyroMisalign {
  static constexpr EffectSpec spec{Effect::GyroMisalign, "gyro_misalign", Components::OffDiagonal, "mrad", 1e3, 0.02,
                                   0.0, true, 0.035, Triad::Gyro, Triad::Gyro};
  static constexpr ImuStage stage = ImuStage::CrossAxis;
  template <class S> static void correct(EffectView v, S& s) { s.gyro = s.gyro - v.off_diagonal() * s.gyro; }
  template <class T> static void couple(EffectView, T& t) {
    for (Eigen::Index k = 0; k < 6; ++k) {
      const auto [i, j] = kOffDiagonal[static_cast<std::size_t>(k)];
      t.add_attitude(k, -(t.C.col(i) * (t.w_b(j) * t.dt)));
    }
  }
};

}  // namespace sinu::est::effects
