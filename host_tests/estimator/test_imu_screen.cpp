// The raw-sample screen: what is clipped and what is only fast. A converter
// at its rail repeats its extreme code; a fast but live signal repeats codes
// by chance when its noise is about one code, and must not be called clipped
// (a false clip widens the attitude covariance by half the rate over the
// run: tens of degrees of yaw sigma in a spin).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "estimator/nav/imu_screen.hpp"

namespace {

using sinu::est::ImuSample;
using sinu::est::ImuScreen;
using sinu::est::ImuScreenConfig;
using sinu::est::ScreenVerdict;

constexpr double kDegToRad = 0.017453292519943295;
constexpr double kLsb2000_rad_s = 2000.0 * kDegToRad / 32768.0;  // a 16-bit gyro at +-2000 deg/s

double quantise(double v, double lsb) { return std::round(v / lsb) * lsb; }

ImuSample sample(double t, double gz, double az = -9.80665) {
  ImuSample s;
  s.t_s = t;
  s.specific_force_b_m_s2 = {0.0, 0.0, az};
  s.angular_rate_b_rad_s = {0.0, 0.0, gz};
  return s;
}

TEST(ImuScreen, AFastSpinThatRepeatsCodesIsNotClipped) {
  // 180 deg/s (pi rad/s, above the 3-rad/s flat-top floor), 100 Hz, noise
  // of one code: three equal codes in a row happen every second or so.
  ImuScreen screen;
  screen.configure(ImuScreenConfig{});
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0.0, kLsb2000_rad_s);
  int clipped = 0, repeats = 0;
  double last = 0.0;
  for (int n = 0; n < 2000; ++n) {
    const double gz = quantise(M_PI + noise(rng), kLsb2000_rad_s);
    repeats += gz == last;
    last = gz;
    std::uint8_t axes = 0;
    ASSERT_EQ(screen.screen(sample(0.01 * n, gz), axes), ScreenVerdict::Keep);
    clipped += axes != 0;
  }
  EXPECT_GT(repeats, 200);  // the case is real: codes do repeat
  EXPECT_EQ(clipped, 0);
}

TEST(ImuScreen, AGyroPeggedAtItsFullScaleIsClippedAndItsRailRemembered) {
  // +-250 deg/s, range not configured: found from the flat top alone.
  const double rail = quantise(250.0 * kDegToRad, 250.0 * kDegToRad / 32768.0);
  ImuScreen screen;
  screen.configure(ImuScreenConfig{});
  std::uint8_t axes = 0;
  double t = 0.0;
  for (int n = 0; n < 10; ++n) {
    ASSERT_EQ(screen.screen(sample(t += 0.01, 2.0 + 0.001 * n), axes), ScreenVerdict::Keep);
    EXPECT_EQ(axes, 0);  // below any rail
  }
  for (int n = 0; n < 20; ++n) {
    screen.screen(sample(t += 0.01, rail), axes);
    // flat_top_repeats = 3: the third equal code on is clipped.
    if (n >= 2) {
      EXPECT_EQ(axes, 1u << 5) << n;
    }
  }
  screen.screen(sample(t += 0.01, 3.0), axes);
  EXPECT_EQ(axes, 0);
  screen.screen(sample(t += 0.01, -rail), axes);  // one sample at the rail, either sign: remembered
  EXPECT_EQ(axes, 1u << 5);
}

TEST(ImuScreen, AnAccelerometerPeggedAtFourGIsClippedAndAConfiguredRangeIsUsed) {
  ImuScreen screen;
  screen.configure(ImuScreenConfig{});
  std::uint8_t axes = 0;
  for (int n = 0; n < 5; ++n) screen.screen(sample(0.01 * n, 0.0, -4.0 * 9.80665), axes);
  EXPECT_EQ(axes, 1u << 2);
  ImuScreenConfig known;
  known.gyro_range_rad_s = 500.0 * kDegToRad;
  screen.configure(known);
  screen.screen(sample(1.0, 0.99 * 500.0 * kDegToRad), axes);  // beyond clip_fraction 0.98: clipped at once
  EXPECT_EQ(axes, 1u << 5);
}

TEST(ImuScreen, AnUnusualFullScaleNeedsALongerFlatTop) {
  // A +-5-g part (between the common 4 and 6 g): ten equal codes, not three.
  ImuScreen screen;
  screen.configure(ImuScreenConfig{});
  std::uint8_t axes = 0;
  for (int n = 0; n < 20; ++n) {
    screen.screen(sample(0.01 * n, 0.0, -5.0 * 9.80665), axes);
    EXPECT_EQ(axes != 0, n >= 9) << n;
  }
}

TEST(ImuScreen, NonFiniteAndNonIncreasingSamplesAreDropped) {
  ImuScreen screen;
  screen.configure(ImuScreenConfig{});
  std::uint8_t axes = 0;
  EXPECT_EQ(screen.screen(sample(1.0, 0.0), axes), ScreenVerdict::Keep);
  EXPECT_EQ(screen.screen(sample(1.0, 0.0), axes), ScreenVerdict::NotIncreasing);
  EXPECT_EQ(screen.screen(sample(0.5, 0.0), axes), ScreenVerdict::NotIncreasing);
  EXPECT_EQ(screen.screen(sample(1.01, std::numeric_limits<double>::quiet_NaN()), axes), ScreenVerdict::NonFinite);
  EXPECT_EQ(screen.screen(sample(1.02, 0.0), axes), ScreenVerdict::Keep);
}

}  // namespace
