// imu.csv rows with part of the IMU (dataset/imu_row_merger.hpp): the
// contract's empty fields where a sensor had no new sample, as a logger that
// writes each sensor as it arrives gives them.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "firmware/host/dataset/imu_row_merger.hpp"

using namespace sinu::dataset;

namespace {

// A row at t; NaN leaves a triad (or the temperature) empty.
ImuRow row(double t, double accel, double gyro, double mag = NAN, double temp = NAN) {
  ImuRow r;
  r.row.clear(imu_col::count);
  r.row.set(imu_col::t, t);
  for (std::size_t i = 0; i < 3; ++i) {
    if (!std::isnan(accel)) r.row.set(imu_col::ax + i, accel + static_cast<double>(i));
    if (!std::isnan(gyro)) r.row.set(imu_col::gx + i, gyro + static_cast<double>(i));
    if (!std::isnan(mag)) r.row.set(imu_col::mx + i, mag + static_cast<double>(i));
  }
  if (!std::isnan(temp)) r.row.set(imu_col::temp, temp);
  return r;
}

std::vector<sinu::est::ImuSample> merge(ImuRowMerger& m, const std::vector<ImuRow>& rows) {
  std::vector<sinu::est::ImuSample> out;
  sinu::est::ImuSample s;
  for (const ImuRow& r : rows) {
    m.add(r);
    while (m.next(s)) out.push_back(s);
  }
  m.finish();
  while (m.next(s)) out.push_back(s);
  return out;
}

}  // namespace

TEST(ImuRowMerger, CompleteRowsPassUnchanged) {
  ImuRowMerger m;
  const auto out = merge(m, {row(1.0, -9.8, 0.01, 20.0, 31.5), row(1.01, -9.7, 0.02)});
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].t_s, 1.0);
  EXPECT_EQ(out[0].specific_force_b_m_s2[2], -9.8 + 2.0);
  EXPECT_EQ(out[0].angular_rate_b_rad_s[1], 0.01 + 1.0);
  EXPECT_TRUE(out[0].has_mag);
  EXPECT_EQ(out[0].mag_b_uT[0], 20.0);
  EXPECT_TRUE(out[0].has_temp);
  EXPECT_EQ(out[0].temp_degC, 31.5);
  EXPECT_FALSE(out[1].has_mag);  // a field goes with one sample only
  EXPECT_FALSE(out[1].has_temp);
  EXPECT_EQ(m.counts().rows_folded + m.counts().accel_held + m.counts().accel_interpolated + m.counts().left_out, 0u);
}

// Accelerometer and gyro on alternate rows (each at 50 Hz, 10 ms apart): every
// gyro row is a sample at its own time, its specific force interpolated
// between the readings before and after it (a ramp: exact), none lost.
TEST(ImuRowMerger, AlternateRowsInterpolateTheAccelerometerToTheGyrosTime) {
  std::vector<ImuRow> rows;
  for (int k = 0; k < 100; ++k) {
    const double t = 100.0 + 0.01 * k;
    rows.push_back(k % 2 == 0 ? row(t, 2.0 * t, NAN) : row(t, NAN, 0.5 * t));
  }
  ImuRowMerger m;
  const auto out = merge(m, rows);
  ASSERT_EQ(out.size(), 50u);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double t = 100.0 + 0.01 * static_cast<double>(2 * i + 1);
    EXPECT_NEAR(out[i].t_s, t, 1e-12);
    EXPECT_NEAR(out[i].angular_rate_b_rad_s[0], 0.5 * t, 1e-12);
    // The last gyro row has no reading after it: held at the one before (t - 0.01).
    const double f = i + 1 < out.size() ? 2.0 * t : 2.0 * (t - 0.01);
    EXPECT_NEAR(out[i].specific_force_b_m_s2[0], f, 1e-9) << i;
  }
  EXPECT_EQ(m.counts().accel_interpolated, 49u);
  EXPECT_EQ(m.counts().accel_held, 1u);
  EXPECT_EQ(m.counts().rows_folded, 50u);
}

// A gyro at twice the accelerometer's rate: every gyro sample kept (before:
// every other row left out); the field on a row of its own goes with the
// next gyro row; gyro rows before any accelerometer reading are left out.
TEST(ImuRowMerger, AFasterGyroKeepsEverySampleAndAFieldRowGoesWithTheNextSample) {
  ImuRowMerger m;
  const auto out = merge(m, {row(0.99, NAN, 7.0), row(1.0, 1.0, 1.0), row(1.005, NAN, NAN, 30.0), row(1.01, NAN, 2.0),
                             row(1.02, 3.0, 3.0)});
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(m.counts().left_out, 1u);
  EXPECT_NEAR(out[1].t_s, 1.01, 1e-12);
  EXPECT_NEAR(out[1].specific_force_b_m_s2[0], 2.0, 1e-9);  // halfway between 1.0 and 3.0
  EXPECT_TRUE(out[1].has_mag);
  EXPECT_EQ(out[1].mag_b_uT[2], 32.0);
  EXPECT_FALSE(out[0].has_mag);
  EXPECT_FALSE(out[2].has_mag);
}

// An accelerometer that falls silent: the gyro samples wait for it at most
// kMaxWaiting rows, then take its last reading, held and counted; order kept.
TEST(ImuRowMerger, ASilentAccelerometerIsHeldAfterAShortWait) {
  std::vector<ImuRow> rows = {row(0.0, 5.0, 0.0)};
  for (int k = 1; k <= 40; ++k) rows.push_back(row(0.01 * k, NAN, 0.0));
  ImuRowMerger m;
  const auto out = merge(m, rows);
  ASSERT_EQ(out.size(), 41u);
  for (std::size_t i = 1; i < out.size(); ++i) {
    EXPECT_GT(out[i].t_s, out[i - 1].t_s);
    EXPECT_EQ(out[i].specific_force_b_m_s2[0], 5.0);
  }
  EXPECT_EQ(m.counts().accel_held, 40u);
}

// Stamps out of order (a live stream's glitch, dropped and counted by the
// navigator): the specific force stays between the two readings, never
// extrapolated from a weight outside 0..1.
TEST(ImuRowMerger, StampsOutOfOrderDoNotExtrapolate) {
  ImuRowMerger m;
  const auto out = merge(m, {row(1.0, 1.0, 1.0), row(0.5, NAN, 2.0), row(1.01, 3.0, NAN), row(1.02, 5.0, 3.0)});
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1].t_s, 0.5);
  EXPECT_EQ(out[1].specific_force_b_m_s2[0], 1.0);  // clamped to the reading before (weight -49 unclamped)
}
