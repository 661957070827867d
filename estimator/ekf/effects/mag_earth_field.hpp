#pragma once
// The Earth's magnetic field, NED [uT], a state so the declination and
// inclination need not be known (PX4 EKF2 does the same); set from the
// attitude at the magnetometer's start. Its error is the invariant one,
// e = dF + [F_hat x] phi (state_layout.hpp): a rotation of the whole solution
// leaves it unchanged, so the magnetometer never claims absolute attitude.
#include "estimator/ekf/effects/effect_spec.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est::effects {

struct MagEarthField {
  // ~0.1 uT over 100 km
  static constexpr EffectSpec spec{Effect::MagEarthField, "mag_earth_field", Components::Xyz, "uT", 1.0, 5.0, 1e-3,
                                   false, 100.0};
  /// y = -A C_bn e - dh (A = S (I - [theta x])): with the invariant error the attitude drops out.
  template <class T> static void magnetometer(EffectView, T& t) {
    if (t.slice.active()) t.H.block(0, t.slice.start, 3, 3) = -t.A * t.C_bn;
  }
  /// e moves with phi: e_k+1 = e_k + [F x] (phi_k+1 - phi_k), after every
  /// other term of the attitude rows is in.
  template <class T> static void couple_last(EffectView v, T& t) {
    Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, T::kMaxCols> dphi = t.Phi.middleRows(t.A, 3);
    dphi.middleCols(t.A, 3) -= Eigen::Matrix3d::Identity();
    t.Phi.middleRows(t.slice.start, 3) += skew(v.vec3()) * dphi;
  }
  /// Feedback: the field turns with the attitude correction (exactly, as the
  /// attitude does), and so does its error, a navigation-frame vector (the
  /// reset Jacobian: without it a large heading correction leaves the field's
  /// covariance pointing the old way and the next turns diverge).
  template <class T> static void feedback(double* v, T& t) {
    const Eigen::Matrix3d R = t.attitude_rotation();
    const Eigen::Vector3d F = R * Eigen::Vector3d(v[0], v[1], v[2]) + t.dx.segment(t.slice.start, 3);
    for (int j = 0; j < 3; ++j) v[j] = F(j);
    t.rotate_block(t.slice, R);
  }
};

}  // namespace sinu::est::effects
