#pragma once
// How much older the magnetometer's reading is than its time stamp [s]: a
// compass read over a slow path (the AK09916 behind the ICM-20948's auxiliary
// I2C master, an external compass polled at 10 Hz, a driver's filter) holds
// the field of the attitude tau ago. In a turn at the body rate w that is the
// body field turned back by w tau (PX4's EKF2_MAG_DELAY):
//   m = S (I - [theta x]) exp(tau [w x]) C_bn F + h
// 0.1 s in a 30-deg/s yaw is 3 deg of heading; level flight shows nothing.
#include "estimator/ekf/effects/effect_spec.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est::effects {

struct MagLatency {
  // A few tens of ms over a bus; a polled or filtered compass up to ~0.3 s
  static constexpr EffectSpec spec{Effect::MagLatency, "mag_latency", Components::One, "s", 1.0, 0.1, 0.0, true,
                                   0.5, Triad::None, Triad::None, Needs::Magnetometer,
                                   "turns, the faster the better (the body rate the field lags)"};
  /// C_b(t - tau) b(t): the body axes tau ago against now, exp(tau [w x]).
  static Eigen::Matrix3d back(EffectView v, const Eigen::Vector3d& rate_b_rad_s) {
    return quat_from_rotation_vector(v.scalar() * rate_b_rad_s).toRotationMatrix();
  }
  /// d/dtau of A exp(tau [w x]) u_b = A (w x u_b'), u_b' the body field at the reading's instant.
  template <class T> static void magnetometer(EffectView, T& t) {
    if (t.slice.active()) t.H.block(0, t.slice.start, 3, 1) = -t.A * t.rate_b.cross(t.u_b);
  }
};

}  // namespace sinu::est::effects
