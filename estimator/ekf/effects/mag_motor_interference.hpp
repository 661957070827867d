#pragma once
// The motors' field on the magnetometer, body [uT per m/s^2]: the current
// that drives the motors follows their thrust, and so does its field,
//   m = S C_bn F + h + k (-f_z - g0),
// -f_z the body-z specific force (a multirotor's thrust per mass; ArduPilot's
// compassmot fits the same k against throttle or current). The hover's share
// is the hard iron's; a climb, a pull-up or a banked turn reveal k.
#include "estimator/earth/wgs84.hpp"
#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct MagMotorInterference {
  // Up to 10 uT per m/s^2: 100 uT per g of thrust, an internal compass on the power wiring.
  static constexpr EffectSpec spec{Effect::MagMotorInterference, "mag_motor_interference", Components::Xyz,
                                   "uT/(m/s^2)", 1.0, 2.0, 0.0, true, 10.0, Triad::None, Triad::None,
                                   Needs::Magnetometer, "thrust changes: climbs and descents, pull-ups, banked turns"};
  /// The thrust beyond a hover's, per unit mass [m/s^2], from the body-z specific force.
  static double thrust_m_s2(const Eigen::Vector3d& specific_force_b_m_s2) {
    return -specific_force_b_m_s2.z() - wgs84::kStandardGravity;
  }
  /// What it adds to the reading [uT].
  static Eigen::Vector3d reading(EffectView k, double thrust_m_s2) { return k.vec3() * thrust_m_s2; }
  template <class T> static void magnetometer(EffectView, T& t) {
    if (t.slice.active()) t.H.block(0, t.slice.start, 3, 3) = -t.thrust_m_s2 * Eigen::Matrix3d::Identity();
  }
};

}  // namespace sinu::est::effects
