// sinu denoise end to end: rows, time alignment, pass band and stop band,
// untouched columns and files, the ends, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "firmware/host/dataset/imu_csv.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

using sinu::test::read_file;
using sinu::test::run_sinu;
namespace col = sinu::dataset::imu_col;

namespace {

const std::string kHeader = "t,ax,ay,az,gx,gy,gz,mx,my,mz,temp\n";
constexpr double kRateHz = 40.0;
constexpr double kT0 = 1203.4;  // t does not start at zero (dataset-format.md)
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Motion at 0.5 Hz (kept) plus a 14 Hz engine line (removed), per channel.
double motion(std::size_t c, double t) { return 0.1 * static_cast<double>(c) + std::sin(kTwoPi * 0.5 * t + static_cast<double>(c)); }
double vibration(double t) { return 0.5 * std::sin(kTwoPi * 14.0 * t); }

std::string make_imu(std::size_t rows) {
  std::ostringstream s;
  s.precision(17);
  s << kHeader;
  for (std::size_t i = 0; i < rows; ++i) {
    const double t = kT0 + static_cast<double>(i) / kRateHz;
    s << t;
    for (std::size_t c = 0; c < 6; ++c) s << ',' << motion(c, t) + vibration(t);
    s << ",21.5,-3.25,40.125,31.0625\n";
  }
  return s.str();
}

std::vector<sinu::dataset::CsvRow> read_imu(const std::string& path) {
  sinu::dataset::CsvReader reader(sinu::dataset::kImuSchema);
  EXPECT_TRUE(reader.open(path)) << reader.error().to_string();
  std::vector<sinu::dataset::CsvRow> rows;
  sinu::dataset::CsvRow row;
  while (reader.next(row) == sinu::dataset::ReadStatus::Row) rows.push_back(row);
  EXPECT_EQ(reader.error().message, "");
  return rows;
}

}  // namespace

TEST(Denoise, KeepsMotionRemovesVibrationAndAlignsTime) {
  sinu::test::TempDir dir;
  const auto in = dir.path() / "in";
  std::filesystem::create_directories(in);
  constexpr std::size_t kRows = 1200;  // 30 s
  std::ofstream(in / "imu.csv") << make_imu(kRows);
  std::ofstream(in / "gps.nmea") << "1203.400,$GPGGA,garbage kept byte for byte*00\n";
  std::ofstream(in / "meta.json") << "{\"imu_rate_hz\": 40}\n";
  const auto out = dir.path() / "out";

  const auto r = run_sinu({"denoise", "--in", in.string(), "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("db4 level 3, delay 63 samples"), std::string::npos) << r.err;
  EXPECT_EQ(read_file((out / "gps.nmea").string()), read_file((in / "gps.nmea").string()));
  EXPECT_EQ(read_file((out / "meta.json").string()), read_file((in / "meta.json").string()));

  const auto rows = read_imu((out / "imu.csv").string());
  ASSERT_EQ(rows.size(), kRows);
  double worst_motion_error = 0.0;
  for (std::size_t i = 0; i < kRows; ++i) {
    const double t = kT0 + static_cast<double>(i) / kRateHz;
    ASSERT_NEAR(rows[i].t(), t, 1e-6);  // t written to the microsecond
    EXPECT_EQ(rows[i].value[col::mx], 21.5);
    EXPECT_EQ(rows[i].value[col::temp], 31.0625);
    if (i < 100 || i + 100 > kRows) continue;  // ends: constant extension, checked below
    for (std::size_t c = 0; c < 6; ++c)
      worst_motion_error = std::max(worst_motion_error, std::abs(rows[i].value[col::ax + c] - motion(c, t)));
  }
  // At 0.5 Hz db4 level 3 passes 0.996 of the amplitude (docs/wavelet.md)
  // with a phase error well under one sample; the 14 Hz line (amplitude 0.5)
  // is cut to < 1 %. Without the delay removal the 63-sample (1.575 s) shift
  // would leave an error of about 1.4 on a unit 0.5 Hz sine.
  EXPECT_LT(worst_motion_error, 0.03);
}

TEST(Denoise, EndsAreFilteredAgainstTheHeldSample) {
  // A constant signal stays exactly constant to the first and the last row:
  // priming holds the first sample, the flush holds the last.
  sinu::test::TempDir dir;
  std::string imu = kHeader;
  for (int i = 0; i < 50; ++i) imu += std::to_string(7.0 + 0.025 * i) + ",0.5,0.5,-9.75,0.01,0.02,0.03,,,,\n";
  dir.write("imu.csv", imu);
  const auto out = dir.path() / "out";
  for (const char* w : {"haar", "db2", "db4", "cdf53", "cdf97"}) {
    const auto r = run_sinu({"denoise", "--in", dir.path().string(), "--out", out.string(), "--wavelet", w, "--levels", "6"});
    ASSERT_EQ(r.exit_code, 0) << r.err;  // 50 rows < the level-6 delay: all rows still come out
    const auto rows = read_imu((out / "imu.csv").string());
    ASSERT_EQ(rows.size(), 50u) << w;
    for (const auto& row : rows) {
      EXPECT_NEAR(row.value[col::az], -9.75, 1e-9) << w;  // 9 significant digits written
      EXPECT_FALSE(row.has(col::mx));                        // empty stays empty
    }
  }
}

TEST(Denoise, EmptyGyroFieldStaysEmptyAndIsCounted) {
  sinu::test::TempDir dir;
  std::string imu = kHeader;
  for (int i = 0; i < 40; ++i)
    imu += std::to_string(1.0 + 0.025 * i) + (i == 20 ? ",0,0,-9.8,,,,,,,\n" : ",0,0,-9.8,0.1,0.1,0.1,,,,\n");
  dir.write("imu.csv", imu);
  const auto out = dir.path() / "out";
  const auto r = run_sinu({"denoise", "--in", dir.path().string(), "--out", out.string(), "--wavelet", "haar"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("3 empty accel/gyro fields"), std::string::npos) << r.err;
  const auto rows = read_imu((out / "imu.csv").string());
  ASSERT_EQ(rows.size(), 40u);
  EXPECT_FALSE(rows[20].has(col::gx));
  EXPECT_NEAR(rows[21].value[col::gx], 0.1, 1e-9);  // bridged by the held value
}

TEST(Denoise, BadInputAndUsage) {
  sinu::test::TempDir dir;
  const auto out = (dir.path() / "out").string();
  EXPECT_EQ(run_sinu({"denoise", "--in", dir.path().string()}).exit_code, 2);  // --out missing
  EXPECT_EQ(run_sinu({"denoise", "--in", dir.path().string(), "--out", out, "--wavelet", "db3"}).exit_code, 2);
  EXPECT_EQ(run_sinu({"denoise", "--in", dir.path().string(), "--out", out, "--levels", "7"}).exit_code, 2);
  EXPECT_EQ(run_sinu({"denoise", "--in", dir.path().string(), "--out", dir.path().string()}).exit_code, 2);

  auto r = run_sinu({"denoise", "--in", dir.path().string(), "--out", out});  // no imu.csv
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("imu.csv"), std::string::npos) << r.err;

  const auto imu = dir.write("imu.csv", kHeader + "1.0,0,0,-9.8,0,0,0,,,,\n1.025,0,0,-9.8,0,nan,0,,,,\n");
  r = run_sinu({"denoise", "--in", dir.path().string(), "--out", out});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(imu + ":3:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'gy'"), std::string::npos) << r.err;
}

TEST(Denoise, TimeGapsAreReported) {
  sinu::test::TempDir dir;
  std::string imu = kHeader;
  for (int i = 0; i < 80; ++i) {
    if (i == 30) continue;
    imu += std::to_string(1.0 + 0.025 * i) + ",0,0,-9.8,0,0,0,,,,\n";
  }
  dir.write("imu.csv", imu);
  const auto r = run_sinu({"denoise", "--in", dir.path().string(), "--out", (dir.path() / "o").string()});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.err.find("1 time gaps"), std::string::npos) << r.err;
}
