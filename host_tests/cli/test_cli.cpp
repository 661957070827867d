// The sinu command: help, exit codes, and inspect dataset's errors.
#include <gtest/gtest.h>

#include <filesystem>

#include "host_tests/support/run_process.hpp"
#include "host_tests/support/shared_data.hpp"
#include "host_tests/support/temp_dir.hpp"

using sinu::test::run_sinu;

namespace {
const std::string kHeader = "t,ax,ay,az,gx,gy,gz,mx,my,mz,temp\n";
}

TEST(Cli, HelpListsEverySubcommand) {
  const auto r = run_sinu({"--help"});
  EXPECT_EQ(r.exit_code, 0);
  for (const char* sub : {"simulate", "denoise", "calibrate", "replay", "diagnose", "inspect", "record", "convert", "fly"})
    EXPECT_NE(r.out.find(sub), std::string::npos) << sub;
}

TEST(Cli, EverySubcommandHasHelp) {
  for (const char* sub : {"simulate", "denoise", "calibrate", "replay", "diagnose", "inspect", "record", "convert", "fly"}) {
    const auto r = run_sinu({sub, "--help"});
    EXPECT_EQ(r.exit_code, 0) << sub;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << sub;
  }
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(run_sinu({}).exit_code, 2);
  EXPECT_EQ(run_sinu({"no-such-mode"}).exit_code, 2);
  EXPECT_EQ(run_sinu({"inspect", "dataset"}).exit_code, 2);  // DIR missing
  EXPECT_EQ(run_sinu({"inspect", "dataset", "a", "--bogus"}).exit_code, 2);
}

TEST(Cli, InspectMalformedDatasetExitsOneWithFileLineColumn) {
  sinu::test::TempDir dir;
  const auto imu = dir.write("imu.csv", kHeader + "1.0,0,0,-9.8,0,0,0,,,,\n1.025,0,0,-9.8,0,zz,0,,,,\n");
  const auto r = run_sinu({"inspect", "dataset", dir.path().string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(imu + ":3:18: field 'gy': not a number 'zz'"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << "no summary for a dataset that failed validation";
}

TEST(Cli, InspectReportsMissingImuAndMissingFolder) {
  sinu::test::TempDir dir;
  auto r = run_sinu({"inspect", "dataset", dir.path().string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("imu.csv: missing"), std::string::npos) << r.err;
  r = run_sinu({"inspect", "dataset", (dir.path() / "nope").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("not a directory"), std::string::npos) << r.err;
}

TEST(Cli, InspectSummarisesAValidDataset) {
  sinu::test::TempDir dir;
  std::string imu = kHeader;
  for (int i = 0; i < 400; ++i) {
    if (i == 200) continue;  // one dropped sample: a gap of 2 periods
    imu += std::to_string(50.0 + 0.025 * i) + ",0,0,-9.8,0,0,0,,,,25\n";
  }
  dir.write("imu.csv", imu);
  dir.write("gps.nmea",
            "50.05,$GNGGA,193400.50,4005.7976080,N,10508.8468980,W,4,21,,1601.474,M,-21.387,M,,*58\n"
            "50.06,$GNGGA,193400.5*00\n");
  const auto r = run_sinu({"inspect", "dataset", dir.path().string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"count\": 399"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"gaps\": 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"corrupt\": 1"), std::string::npos) << r.out;
}

// The magnitudes hint at the units before any replay: gravity ~9.8 m/s^2,
// the Earth's field 22-67 uT. An accelerometer in g and a field in mG are
// named; SI data is not.
TEST(Cli, InspectNamesMagnitudesThatAreNotSi) {
  sinu::test::TempDir dir;
  std::string si = kHeader, other = kHeader;
  for (int i = 0; i < 100; ++i) {
    const std::string t = std::to_string(50.0 + 0.025 * i);
    si += t + ",0.1,0,-9.8,0,0,0,20,0,40,25\n";
    other += t + ",0.01,0,-1.0,0,0,0,200,0,400,25\n";  // g and mG
  }
  std::filesystem::create_directories(dir.path() / "si");
  std::filesystem::create_directories(dir.path() / "other");
  dir.write("si/imu.csv", si);
  dir.write("other/imu.csv", other);
  auto r = run_sinu({"inspect", "dataset", (dir.path() / "si").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("UNITS?"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mean |f| 9.801 m/s^2, mean |m| 44.72 uT"), std::string::npos) << r.out;
  r = run_sinu({"inspect", "dataset", (dir.path() / "other").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("ax, ay, az must be m/s^2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mx, my, mz must be uT"), std::string::npos) << r.out;
}

// An IMU-only dataset (a bench session given to replay by mistake): the INS
// has no position to start from, and says that rather than blaming a
// missing rest period (it was at rest).
TEST(Cli, ReplayWithoutGnssSaysWhyItCannotAlign) {
  sinu::test::TempDir dir;
  std::string imu = kHeader;
  for (int i = 0; i < 400; ++i) imu += std::to_string(50.0 + 0.025 * i) + ",0,0,-9.8,0,0,0,,,,25\n";
  dir.write("imu.csv", imu);
  const auto r = run_sinu({"replay", "--in", dir.path().string(), "--out", dir.file("out")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("NOT ALIGNED"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no GNSS position in the data"), std::string::npos) << r.out;
}

TEST(Cli, DiagnoseWithoutItsRequiredOptionsIsAUsageError) {
  const auto r = run_sinu({"diagnose"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--in"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << "never made-up output";
}

// The decision thresholds are the user's to move, within what they mean: a
// negative log Bayes factor would name effects that make the fit worse.
TEST(Cli, DiagnoseRefusesAThresholdOutsideItsMeaning) {
  const auto r = run_sinu({"diagnose", "--in", ".", "--out", "x", "--min-evidence", "-1"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--min-evidence"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << "never made-up output";
}

TEST(Cli, InspectRealDrive) {
  SINU_REQUIRE_SHARED(dir, "data/real/drive_0708");
  const auto r = run_sinu({"inspect", "dataset", dir});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("54860 rows"), std::string::npos) << r.out;
}
