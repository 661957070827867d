// Velocity from differenced fixes for a receiver without velocity sentences
// (estimator/align/position_velocity.hpp), against motion known exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "estimator/align/position_velocity.hpp"
#include "estimator/earth/wgs84.hpp"

namespace sinu::est {
namespace {

constexpr double kLat = 0.6, kLon = 2.0, kH = 100.0;

/// A fix at t with the unit moved north_m, east_m from (kLat, kLon).
GnssObservation fix_at(double t, double north_m, double east_m, double sigma_m = 1.0) {
  GnssObservation z;
  z.arrival_s = t;
  z.has_position = true;
  z.lat_rad = kLat + north_m / (wgs84::meridian_radius_m(kLat) + kH);
  z.lon_rad = kLon + east_m / ((wgs84::transverse_radius_m(kLat) + kH) * std::cos(kLat));
  z.h_m = kH;
  z.sigma_ned_m = {sigma_m, sigma_m, 2.0 * sigma_m};
  return z;
}

TEST(PositionVelocity, AConstantVelocityIsRecoveredFromFixesOneSecondApart) {
  PositionVelocity pv;
  pv.configure({});
  const double vn = 12.0, ve = -5.0;
  int filled = 0;
  for (int k = 0; k < 26; ++k) {  // 5 Hz for 5 s
    const double t = 0.2 * k;
    GnssObservation z = fix_at(t, vn * t, ve * t);
    const bool ok = pv.fill(z);
    if (t < 1.0 - 1e-9) {
      EXPECT_FALSE(ok) << t;  // no fix a baseline earlier yet
      continue;
    }
    ASSERT_TRUE(ok) << t;
    ++filled;
    EXPECT_TRUE(z.has_velocity && z.velocity_from_positions);
    // The fixes are placed with the radii the differencing uses at a latitude
    // that moves by < 1e-5 rad: mm/s at most.
    EXPECT_NEAR(z.v_ne_m_s.x(), vn, 1e-3);
    EXPECT_NEAR(z.v_ne_m_s.y(), ve, 1e-3);
    // sqrt(0.1 (1 + 1)) / 1 s white, 0.5 m/s lag over 1 s at 1 m/s^2.
    EXPECT_NEAR(z.sigma_vel_m_s, std::hypot(std::sqrt(0.2), 0.5), 1e-9);
  }
  EXPECT_EQ(filled, 21);
}

TEST(PositionVelocity, TheReceiversOwnVelocityAndALongGapAreLeftAlone) {
  PositionVelocity pv;
  pv.configure({});
  GnssObservation a = fix_at(0.0, 0.0, 0.0);
  EXPECT_FALSE(pv.fill(a));
  GnssObservation with = fix_at(1.0, 10.0, 0.0);
  with.has_velocity = true;
  with.v_ne_m_s = {3.0, 4.0};
  EXPECT_FALSE(pv.fill(with));  // the receiver's velocity is kept as it is
  EXPECT_EQ(with.v_ne_m_s.x(), 3.0);
  EXPECT_FALSE(with.velocity_from_positions);
  GnssObservation late = fix_at(5.0, 50.0, 0.0);  // 4 s after the last fix: beyond max_baseline_s
  EXPECT_FALSE(pv.fill(late));
  EXPECT_FALSE(late.has_velocity);
  GnssObservation no_position;
  no_position.arrival_s = 6.0;
  EXPECT_FALSE(pv.fill(no_position));
}

}  // namespace
}  // namespace sinu::est
