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

// A unit restarted in a level turn at 60 deg of bank (35 m/s, 2 g, the
// velocity turning at g tan(60 deg) / V = 0.49 rad/s; an independent
// aerobatic flight): judged against gravity alone its 2.0x was refused for
// the rest of the flight. The GNSS velocity's turn makes the reference 2 g.
// The same accelerometer in g is still refused, and so it is when a velocity
// glitch (300 m/s off for one epoch) inflates the reference.
struct SteepTurn {
  double accel_unit = 1.0;  // 1 / 9.80665: the accelerometer in g
  bool glitch = false;
  SensorScaleCheck c;
  bool run() {
    c.configure({});
    const double V = 35.0, bank = M_PI / 3.0, omega = kG * std::tan(bank) / V;
    for (int i = 1; i <= 300; ++i) {  // 3 s at 100 Hz, GNSS at 5 Hz
      const double t = i * kDt;
      c.add_sample(accel_unit * Eigen::Vector3d(0.0, 0.0, -kG / std::cos(bank)),
                   Eigen::Vector3d(0.0, omega * std::sin(bank), omega * std::cos(bank)), kDt);
      if (i % 20 != 0) continue;
      Eigen::Vector2d v(V * std::cos(omega * t), V * std::sin(omega * t));
      if (glitch && i == 140) v.x() += 300.0;
      c.add_gnss_velocity(t, v);
    }
    return c.accel_plausible(kG);
  }
};

TEST(SensorScaleCheck, ARestartInASteepTurnIsNotAUnitError) {
  SteepTurn turn;
  EXPECT_TRUE(turn.run());
  // The first 0.8 s has no acceleration yet (the first velocity at 0.2 s,
  // the next 0.6 s later): gravity alone. The mean reference is then
  // (0.8 x 1 + 2.2 x 2) / 3 = 1.73 g and the accelerometer's 2 g 1.16x of it.
  EXPECT_NEAR(turn.c.verdict().expected_over_gravity, 1.73, 0.02);
  EXPECT_NEAR(turn.c.verdict().specific_force_over_gravity, 1.16, 0.02);
  for (const bool glitch : {false, true}) {
    SteepTurn in_g;
    in_g.accel_unit = 1.0 / kG;
    in_g.glitch = glitch;
    EXPECT_FALSE(in_g.run()) << "glitch " << glitch;
    EXPECT_LT(in_g.c.verdict().specific_force_over_gravity, 0.15) << "glitch " << glitch;
  }
}

// A loop: NMEA has no vertical velocity, so the pull-up is not in the
// reference; the band's 2.5x holds its circle's 1.9 g (2.8 g at the bottom,
// 0.8 g at the top, 35 m/s on a 70-m radius).
TEST(SensorScaleCheck, ALoopIsWithinTheBand) {
  SensorScaleCheck c;
  c.configure({});
  const double V = 35.0, q = V / 70.0;
  for (int i = 1; i <= 1257; ++i) {  // one loop, 12.57 s
    const double theta = q * i * kDt;  // pitch
    // Body z: centripetal V q towards the centre plus gravity's component.
    c.add_sample(Eigen::Vector3d(-kG * std::sin(theta), 0.0, -(V * q + kG * std::cos(theta))), Eigen::Vector3d(0, q, 0),
                 kDt);
    if (i % 20 == 0) c.add_gnss_velocity(i * kDt, Eigen::Vector2d(V * std::cos(theta), 0.0));
  }
  EXPECT_TRUE(c.accel_plausible(kG));
  // The reference has the loop's horizontal acceleration (V q sin(theta)),
  // not its vertical one: above 1 g, short of the accelerometer's 1.9 g.
  EXPECT_GT(c.verdict().expected_over_gravity, 1.2);
  EXPECT_GT(c.verdict().specific_force_over_gravity, 1.1);
}

}  // namespace
}  // namespace sinu::est
