// The INS velocity history a lagged GNSS velocity is taken back with
// (estimator/nav/velocity_history.hpp).
#include <gtest/gtest.h>

#include "estimator/nav/velocity_history.hpp"

namespace sinu::est {
namespace {

// A roll-in's acceleration: a = j t (constant jerk), so v = j t^2 / 2 and the
// mean acceleration over [t - tau, t] is j (t - tau / 2), which a smoothed
// acceleration (lagging its time constant) is not. Fed at 40 Hz as the
// strapdown's velocity steps.
TEST(VelocityHistory, MeanAccelerationOverTheLagOfAConstantJerk) {
  VelocityHistory h;
  const double jerk = 2.5, dt = 0.025;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int k = 1; k <= 80; ++k) {
    const double t = k * dt;
    const Eigen::Vector3d v_next(0.5 * jerk * t * t, -0.25 * jerk * t * t, 0.0);
    h.add(t, v_next - v);  // the strapdown's step only: a filter correction is not added
    v = v_next;
  }
  const double t_end = 80 * dt;
  for (double tau : {0.1, 0.125, 0.2, 0.5}) {
    Eigen::Vector3d a;
    ASSERT_TRUE(h.mean_accel(t_end, tau, a)) << tau;
    // Between samples the history is linear: at tau = 0.125 (between 40-Hz
    // points) the quadratic's chord misses by at most j dt^2 / 8 / tau.
    const double bound = jerk * dt * dt / 8.0 / tau + 1e-9;
    EXPECT_NEAR(a.x(), jerk * (t_end - tau / 2.0), bound) << tau;
    EXPECT_NEAR(a.y(), -0.5 * jerk * (t_end - tau / 2.0), bound) << tau;
    EXPECT_NEAR(a.z(), 0.0, 1e-12);
  }
}

TEST(VelocityHistory, SaysWhenItDoesNotReachBack) {
  VelocityHistory h;
  Eigen::Vector3d a(7.0, 7.0, 7.0);
  EXPECT_FALSE(h.mean_accel(1.0, 0.1, a));
  for (int k = 0; k <= 400; ++k) h.add(k * 0.005, Eigen::Vector3d(0.005, 0.0, 0.0));  // 1 m/s^2 for 2 s
  EXPECT_FALSE(h.mean_accel(2.0, 1.5, a)) << "kept: the last second";
  EXPECT_FALSE(h.mean_accel(2.1, 0.1, a)) << "after the latest step";
  EXPECT_FALSE(h.mean_accel(2.0, 0.0, a));
  EXPECT_EQ(a, Eigen::Vector3d(7.0, 7.0, 7.0)) << "untouched when false";
  ASSERT_TRUE(h.mean_accel(2.0, 0.3, a));
  EXPECT_NEAR(a.x(), 1.0, 1e-9);
  h.clear();
  EXPECT_FALSE(h.mean_accel(2.0, 0.3, a));
}

}  // namespace
}  // namespace sinu::est
