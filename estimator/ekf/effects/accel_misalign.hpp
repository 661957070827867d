#pragma once
// The accelerometer's cross-axis sensitivity (misalignment), off-diagonal:
//   f = (I - M) f,  M(i,j): axis i senses axis j   [rad, shown in mrad]
// Its error moves sensor axis i by the other axis's reading.
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct AccelMisalign {
  // consumer MEMS: up to ~2 % (20 mrad)
  static constexpr EffectSpec spec{Effect::AccelMisalign, "accel_misalign", Components::OffDiagonal, "mrad", 1e3,
                                   0.02, 0.0, true, 0.035, Triad::Accel, Triad::Accel};
  static constexpr ImuStage stage = ImuStage::CrossAxis;
  template <class S> static void correct(EffectView v, S& s) { s.accel = s.accel - v.off_diagonal() * s.accel; }
  template <class T> static void couple(EffectView, T& t) {
    for (Eigen::Index k = 0; k < 6; ++k) {
      const auto [i, j] = kOffDiagonal[static_cast<std::size_t>(k)];
      t.add_velocity(k, t.C.col(i) * (t.f_b(j) * t.dt));
    }
  }
};

}  // namespace sinu::est::effects
