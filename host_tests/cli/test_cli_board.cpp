// sinu inspect nmea / inspect recording / convert / record from the command line.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "host_tests/support/nmea_text.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/shared_data.hpp"
#include "host_tests/support/temp_dir.hpp"

using sinu::test::run_sinu;

namespace {
std::vector<nlohmann::json> json_lines(const std::string& out) {
  std::vector<nlohmann::json> v;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) v.push_back(nlohmann::json::parse(line));
  return v;
}
const std::string kGga = sinu::test::nmea_with_checksum("GNGGA,101520.40,3024.51234,N,11421.12345,E,1,12,0.8,45.3,M,-2.1,M,,");
const std::string kGst = sinu::test::nmea_with_checksum("GNGST,101520.40,1.2,,,,0.9,0.8,1.5");
const std::string kRmc = sinu::test::nmea_with_checksum("GNRMC,101520.40,A,3024.51234,N,11421.12345,E,10.0,90.0,220326,,,A");
}  // namespace

TEST(CliInspectNmea, GpsNmeaGivesOneJsonLinePerFixThenCounters) {
  sinu::test::TempDir dir;
  const auto file = dir.write("gps.nmea", "10.0," + kGga + "\n10.1," + kRmc + "\n10.2," + kGst + "\n10.3,$GPGGA,bad*00\n");
  const auto r = run_sinu({"inspect", "nmea", file, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto lines = json_lines(r.out);
  ASSERT_EQ(lines.size(), 2u);
  const auto& fix = lines[0];
  EXPECT_EQ(fix["utc"], "2026-03-22T10:15:20.400Z");
  EXPECT_NEAR(fix["lat"].get<double>(), 30.0 + 24.51234 / 60.0, 1e-12);
  EXPECT_DOUBLE_EQ(fix["alt_msl"].get<double>(), 45.3);
  EXPECT_DOUBLE_EQ(fix["geoid_sep"].get<double>(), -2.1);
  EXPECT_EQ(fix["quality"], 1);
  EXPECT_EQ(fix["sats"], 12);
  EXPECT_DOUBLE_EQ(fix["hdop"].get<double>(), 0.8);
  EXPECT_NEAR(fix["speed_m_s"].get<double>(), 10.0 * 1852.0 / 3600.0, 1e-12);
  EXPECT_DOUBLE_EQ(fix["course_deg"].get<double>(), 90.0);
  EXPECT_DOUBLE_EQ(fix["sigma_alt_m"].get<double>(), 1.5);
  const auto& c = lines[1]["counters"];
  EXPECT_EQ(c["good"], 3);
  EXPECT_EQ(c["bad_checksum"], 1);
  EXPECT_EQ(c["fixes"], 1);
}

TEST(CliInspectNmea, EmptyFieldsAreNullNeverZero) {
  sinu::test::TempDir dir;
  const auto file = dir.write("cap.log", "# a comment\n" + sinu::test::nmea_with_checksum("GPGGA,101520.40,,,,,0,00,,,M,,M,,") + "\r\n");
  const auto r = run_sinu({"inspect", "nmea", file, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto lines = json_lines(r.out);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_TRUE(lines[0]["lat"].is_null());
  EXPECT_TRUE(lines[0]["alt_msl"].is_null());
  EXPECT_FALSE(lines[0].contains("sigma_lat_m")) << "sigmas only when GST is present";
  EXPECT_EQ(lines[1]["counters"]["comment_lines"], 1);
}

TEST(CliInspectNmea, GpsdLogCountsMatchTheLibrary) {
  SINU_REQUIRE_SHARED(log, "data/nmea-gpsd/isync.log");
  const auto r = run_sinu({"inspect", "nmea", log, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto lines = json_lines(r.out);
  const auto& c = lines.back()["counters"];
  EXPECT_EQ(c["resumed"], 1) << "the spliced GSV is put back together";
  EXPECT_EQ(c["fixes_with_position"], 12);
}

TEST(CliInspectNmea, MissingFileExitsOne) {
  const auto r = run_sinu({"inspect", "nmea", "/nonexistent/x.log"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("/nonexistent/x.log"), std::string::npos);
}

TEST(CliInspectRecording, SummarisesAndReportsATruncatedTail) {
  sinu::test::TempDir dir;
  const auto d = dir.path() / "d";
  std::filesystem::create_directories(d);
  {
    std::ofstream imu(d / "imu.csv");
    imu << "t,ax,ay,az,gx,gy,gz,mx,my,mz,temp\n";
    for (int k = 0; k < 80; ++k) imu << 100.0 + k * 0.025 << ",0.1,0,-9.8,0,0,0.01,20,0,40,25\n";
    std::ofstream gps(d / "gps.nmea");
    gps << "100.5," << kGga << "\n";
  }
  const std::string raw = dir.file("r.raw");
  auto r = run_sinu({"convert", d.string(), raw});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_sinu({"inspect", "recording", raw});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("gpio edges     80  (40.00 Hz)"), std::string::npos) << r.out;
  std::filesystem::resize_file(raw, std::filesystem::file_size(raw) - 3);
  r = run_sinu({"inspect", "recording", raw});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.err.find("truncated"), std::string::npos) << r.err;
  EXPECT_EQ(run_sinu({"inspect", "recording", d.string() + "/imu.csv"}).exit_code, 1);
}

TEST(CliConvert, ReportsBadInputWithFileAndLine) {
  sinu::test::TempDir dir;
  dir.write("imu.csv", "t,ax,ay,az,gx,gy,gz,mx,my,mz,temp\n1,0,0,-9.8,0,0,0,,,,\n2,0,zz,-9.8,0,0,0,,,,\n");
  const auto r = run_sinu({"convert", dir.path().string(), dir.file("o.raw")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("imu.csv:3:"), std::string::npos) << r.err;
  EXPECT_EQ(run_sinu({"convert", dir.path().string(), dir.file("o.raw"), "--mounting", "x,x,z"}).exit_code, 2);
}

TEST(CliRecord, FailsCleanlyWithoutTheBoardsDevices) {
  const auto r = run_sinu({"record", "--out", "/tmp/never.raw", "--i2c", "/nonexistent/i2c-9", "--duration", "1"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("/nonexistent/i2c-9"), std::string::npos) << r.err;
}

TEST(CliFly, FailsCleanlyWithoutTheBoardsDevices) {
  sinu::test::TempDir dir;
  const std::string cfg = dir.write("sinu.toml", "[imu]\ni2c = \"/nonexistent/i2c-9\"\n[outputs.log]\nenabled = false\n");
  const auto r = run_sinu({"fly", "--config", cfg, "--duration", "1"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("/nonexistent/i2c-9"), std::string::npos) << r.err;
  // The command line overrides the file: the bus named is the option's.
  const auto o = run_sinu({"fly", "--config", cfg, "--i2c", "/nonexistent/i2c-7", "--duration", "1"});
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_NE(o.err.find("/nonexistent/i2c-7"), std::string::npos) << o.err;
  EXPECT_EQ(o.err.find("/nonexistent/i2c-9"), std::string::npos) << o.err;
}

TEST(CliFly, ABadConfigurationNamesFileLineAndKeyAndExitsTwo) {
  sinu::test::TempDir dir;
  const std::string cfg = dir.write("sinu.toml", "[imu]\nrate_hz = 40\nadress = 0x68\n");
  const auto r = run_sinu({"fly", "--config", cfg, "--emulate", "/nonexistent"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(cfg + ":3: imu.adress: unknown key"), std::string::npos) << r.err;
  const auto f = run_sinu({"fly", "--emulate", dir.path().string(), "--fault", "i2c-stop:10"});
  EXPECT_EQ(f.exit_code, 2);
  EXPECT_NE(f.err.find("--fault"), std::string::npos) << f.err;
}
