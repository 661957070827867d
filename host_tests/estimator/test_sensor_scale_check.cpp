// The units check (estimator/nav/sensor_scale_check.hpp) on synthetic
// samples: what it refuses, and what it must let through.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "estimator/nav/sensor_scale_check.hpp"

namespace sinu::est {
namespace {

constexpr double kG = 9.80665;
constexpr double kDt = 0.01;  // a 100-Hz IMU, GNSS epochs every 0.2 s

/// `seconds` of samples at rest with gyro noise `gyro_sigma` (rad/s, white),
/// then a GNSS epoch at speed 0 every 0.2 s; true while the gyro is plausible.
bool at_rest(SensorScaleCheck& c, double seconds, double gyro_sigma, std::mt19937& rng) {
  static double t_s = 0.0;
  std::normal_distribution<double> n(0.0, 1.0);
  bool plausible = true;
  for (int i = 1; i <= static_cast<int>(seconds / kDt); ++i) {
    const Eigen::Vector3d f(0.01 * n(rng), 0.01 * n(rng), -kG + 0.01 * n(rng));
    const Eigen::Vector3d w = gyro_sigma * Eigen::Vector3d(n(rng), n(rng), n(rng)) + Eigen::Vector3d(0.1, 0, 0);
    c.add_sample(f, w, kDt);
    t_s += kDt;
    if (i % 20 == 0) plausible = c.gyro_plausible(t_s, 0.0);
  }
  return plausible;
}

TEST(SensorScaleCheck, AGyroInDegreesPerSecondIsRefusedAGyroInRadiansIsNot) {
  std::mt19937 rng(3);
  SensorScaleCheck rad, deg;
  rad.configure({});
  deg.configure({});
  // A consumer gyro's 0.003 rad/s with a 0.1 rad/s turn-on bias (the mean is no test).
  EXPECT_TRUE(at_rest(rad, 10.0, 0.003, rng));
  EXPECT_LT(rad.verdict().gyro_std_at_rest_rad_s, 0.005);
  EXPECT_FALSE(at_rest(deg, 10.0, 0.003 * 180.0 / M_PI, rng));
  EXPECT_TRUE(deg.verdict().gyro_refused);
  EXPECT_TRUE(deg.refused());
}

// A second of scatter (a hand turning the unit about the vertical at rest)
// is not a unit: its 1-s average stays above the bound ~3 s after it, and
// refusal takes gyro_persist_s (5 s) of judged epochs above it.
TEST(SensorScaleCheck, ABriefScatterIsNotRefused) {
  std::mt19937 rng(4);
  SensorScaleCheck c;
  c.configure({});
  EXPECT_TRUE(at_rest(c, 5.0, 0.003, rng));
  EXPECT_FALSE(at_rest(c, 1.0, 0.2, rng));  // held: these epochs align nothing
  EXPECT_FALSE(c.refused());
  EXPECT_TRUE(at_rest(c, 5.0, 0.003, rng));
  EXPECT_FALSE(c.refused());
}

// A quadcopter hovering (the GNSS says still, the accelerometer is quiet)
// spins on the spot: 1 s up to 90 deg/s about the vertical, 3 s at it, 1 s
// down, again and again (the independent simulator's quadcopter did this before
// its first leg, and the check refused the unit for the rest of the flight).
// Its rate scatters 0.45 rad/s about the vertical while it speeds up; across
// gravity only the noise. The same gyro in deg/s is still refused.
TEST(SensorScaleCheck, AHoverSpinAboutTheVerticalIsNotAUnitError) {
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0.0, 1.0);
  for (const double units : {1.0, 180.0 / M_PI}) {
    SensorScaleCheck c;
    c.configure({});
    double t_s = 0.0;
    bool ever_refused = false;
    for (int i = 0; i < 6000; ++i) {  // 60 s: twelve 5-s spins
      t_s += kDt;
      const double phase = std::fmod(t_s, 5.0);
      const double yaw_rate = M_PI / 2.0 * std::clamp(std::min(phase, 5.0 - phase), 0.0, 1.0);
      const Eigen::Vector3d f(0.01 * n(rng), 0.01 * n(rng), -kG + 0.01 * n(rng));
      const Eigen::Vector3d w = units * (0.003 * Eigen::Vector3d(n(rng), n(rng), n(rng)) + Eigen::Vector3d(0, 0, yaw_rate));
      c.add_sample(f, w, kDt);
      if (i % 20 == 0) c.gyro_plausible(t_s, 0.0);
      ever_refused = ever_refused || c.refused();
    }
    EXPECT_EQ(ever_refused, units > 1.0) << "units " << units;
  }
}

// Moving (the GNSS says so) or a shaking accelerometer: not judged at all.
TEST(SensorScaleCheck, MovingOrShakingIsNotJudged) {
  SensorScaleCheck c;
  c.configure({});
  for (int i = 0; i < 1000; ++i) c.add_sample(Eigen::Vector3d(0, 0, -kG), Eigen::Vector3d(i % 2 ? 1.0 : -1.0, 0, 0), kDt);
  EXPECT_TRUE(c.gyro_plausible(10.0, 5.0));  // moving
  EXPECT_TRUE(c.gyro_plausible(20.0, NAN));  // no GNSS velocity
  EXPECT_TRUE(std::isnan(c.verdict().gyro_std_at_rest_rad_s));
}

TEST(SensorScaleCheck, AccelerometerAndFieldAgainstGravityAndTheModel) {
  SensorScaleCheck si, g;
  si.configure({});
  g.configure({});
  for (int i = 0; i < 100; ++i) {
    si.add_sample(Eigen::Vector3d(0.3, 0, -kG), Eigen::Vector3d::Zero(), kDt);
    g.add_sample(Eigen::Vector3d(0.03, 0, -1.0), Eigen::Vector3d::Zero(), kDt);
  }
  EXPECT_TRUE(si.accel_plausible(kG));
  EXPECT_FALSE(g.accel_plausible(kG));
  EXPECT_NEAR(g.verdict().specific_force_over_gravity, 1.0 / kG, 1e-3);
  // A 50-uT model field: 30 uT of hard iron either way passes, mG (10x) and G (0.01x) do not.
  EXPECT_TRUE(si.field_plausible(80.0, 50.0));
  EXPECT_TRUE(si.field_plausible(20.0, 50.0));
  EXPECT_FALSE(si.field_plausible(500.0, 50.0));
  EXPECT_FALSE(si.field_plausible(0.5, 50.0));
  EXPECT_EQ(si.verdict().mag_refused_samples, 2u);
  EXPECT_TRUE(si.field_plausible(500.0, NAN));  // no model: not judged
}

}  // namespace
}  // namespace sinu::est
