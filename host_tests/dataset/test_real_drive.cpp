// The real car drive in ../shared/data/real/drive_0708 reads completely.
// Expected counts are independent of our reader: `wc -l` of each file minus
// its header, and 3 sentences (GGA, RMC, GST) per epoch as meta.json states.
#include <gtest/gtest.h>

#include "firmware/host/dataset/dataset_summary.hpp"
#include "host_tests/support/shared_data.hpp"

using namespace sinu::dataset;

TEST(RealDrive0708, ReadsCompletelyWithExpectedCounts) {
  SINU_REQUIRE_SHARED(dir, "data/real/drive_0708");
  DatasetSummary s;
  Diagnostic err;
  ASSERT_TRUE(summarize_dataset(DatasetPaths{dir}, s, err)) << err.to_string();
  EXPECT_EQ(s.imu.time.count(), 54860u);  // wc -l imu.csv = 54861
  EXPECT_EQ(s.imu.accel_rows, 54860u);
  EXPECT_EQ(s.imu.mag_rows, 0u) << "no magnetometer: empty fields stay empty";
  EXPECT_EQ(s.imu.temp_rows, 0u);
  EXPECT_NEAR(s.imu.time.nominal_rate_hz(), 100.0, 1.0);
  ASSERT_TRUE(s.gps.has_value());
  EXPECT_EQ(s.gps->lines, 6591u);  // wc -l gps.nmea
  EXPECT_EQ(s.gps->sentences.good, 6591u);
  EXPECT_EQ(s.gps->sentences.corrupt(), 0u);
  EXPECT_EQ(s.gps->epochs, 6591u / 3u);
  EXPECT_EQ(s.gps->fixes.count(), 2197u);  // 2189 RTK-fixed + 8 float epochs (meta.json)
  EXPECT_EQ(s.gps->fixes_with_sigma, 2197u);
  EXPECT_NEAR(s.gps->fixes.nominal_rate_hz(), 4.0, 0.01);
  ASSERT_TRUE(s.truth.has_value());
  EXPECT_EQ(s.truth->time.count(), 2197u);  // wc -l truth.csv = 2198
  EXPECT_EQ(s.truth->attitude_rows, 0u);
  ASSERT_TRUE(s.meta.has_value());
  EXPECT_EQ(*s.meta->imu_rate_hz, 100.0);
}
