#pragma once
// The GNSS antenna's offset from the IMU, body FRD [m]: the receiver measures
// the antenna, p_ant = p + C_nb l, v_ant = v + C_nb (w x l). Carried as a
// value (configured) even when not a state; as a state it shows in rotations.
#include "estimator/ekf/effects/effect_spec.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est::effects {

struct LeverArm {
  // A configuration 10 cm off matters against a decimetre receiver (the configured value is --lever-arm)
  static constexpr EffectSpec spec{Effect::LeverArm, "lever_arm", Components::Xyz, "m", 1.0, 1.0, 0.0, true, 3.0,
                                   Triad::None, Triad::None, Needs::Nothing,
                                   "turns (the arm's velocity w x l) and a level attitude change", 0.1};
  /// Position: the predicted antenna is C l further; d(C_hat l)/dphi = [C l x], d/dl = -C.
  template <class T> static void gnss_position(EffectView v, T& t) {
    const Eigen::Vector3d lever_n = t.C * v.vec3();
    t.antenna_offset_n += lever_n;
    t.H.block(0, t.att, 3, 3) = skew(lever_n);
    if (t.slice.active()) t.H.block(0, t.slice.start, 3, 3) = -t.C;
  }
  /// Velocity: C (w x l); horizontal rows.
  template <class T> static void gnss_velocity(EffectView v, T& t) {
    const Eigen::Vector3d lever_vel_n = t.C * t.w_b.cross(v.vec3());
    t.antenna_velocity_n += lever_vel_n;
    t.H.block(0, t.att, 2, 3) = skew(lever_vel_n).template topRows<2>();
    if (t.slice.active()) t.H.block(0, t.slice.start, 2, 3) = -(t.C * skew(t.w_b)).template topRows<2>();
  }
};

}  // namespace sinu::est::effects
