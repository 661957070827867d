#pragma once
// The magnetometer's soft iron, the symmetric deviation D of S = I + D
// (steel nearby: up to ~20 %): m = (I + D) C_bn F + h; states xx yy zz xy xz yz.
// A scale common to xx, yy, zz trades against the Earth field's strength.
// u is the Earth field in the magnetometer's axes (after mag_misalign).
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct MagSoftIron {
  static constexpr EffectSpec spec{Effect::MagSoftIron, "mag_soft_iron", Components::Symmetric, "-", 1.0, 0.2, 0.0,
                                   true, 0.3, Triad::None, Triad::None, Needs::Magnetometer,
                                   "a full turn in heading (and some bank)"};
  /// d(S u)/dD for D = [xx yy zz xy xz yz], u the Earth field in the magnetometer's axes.
  template <class T> static void magnetometer(EffectView, T& t) {
    if (!t.slice.active()) return;
    const Eigen::Vector3d& u = t.u;
    Eigen::Matrix<double, 3, 6> J;
    J << u.x(), 0.0, 0.0, u.y(), u.z(), 0.0,  //
        0.0, u.y(), 0.0, u.x(), 0.0, u.z(),   //
        0.0, 0.0, u.z(), 0.0, u.x(), u.y();
    t.H.block(0, t.slice.start, 3, 6) = -J;
  }
};

}  // namespace sinu::est::effects
