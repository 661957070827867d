#pragma once
// The magnetometer's axes turned against the IMU's by small angles theta
// (a compass on a mast or a separate board, mounted a few degrees off):
//   m = S (I - [theta x]) C_bn F + h   [rad, shown in mrad]
// Level, a turn about the vertical is the declination's (the Earth field is a
// state); banks and pitch changes separate them.
#include "estimator/ekf/effects/effect_spec.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est::effects {

struct MagMisalign {
  static constexpr EffectSpec spec{Effect::MagMisalign, "mag_misalign", Components::Xyz, "mrad", 1e3, 0.05, 0.0,
                                   true, 0.1, Triad::None, Triad::None, Needs::Magnetometer,
                                   "banked turns and pitch changes (level, a turn about the vertical looks like the declination)"};
  /// d(S (I - [theta x]) u_b)/dtheta = S [u_b x], u_b = C_bn F the Earth field in the body.
  template <class T> static void magnetometer(EffectView, T& t) {
    if (t.slice.active()) t.H.block(0, t.slice.start, 3, 3) = -t.S * skew(t.u_b);
  }
};

}  // namespace sinu::est::effects
