// sinu fly's configuration file: the shipped default file is the code's
// defaults (and the command line's), every kind of error names the file, the
// line and the dotted key, and a partial file keeps the other defaults.
#include <gtest/gtest.h>

#include <string>
#include <toml++/toml.h>

#include "drivers/imu/icm20948.hpp"
#include "firmware/board/config/fly_config.hpp"
#include "firmware/board/config/fly_setup.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace {

using sinu::board::FlyConfig;

const std::string kShipped = std::string(SINU_SOURCE_DIR) + "/firmware/board/package/sinu.toml";

/// Loads `text` as sinu.toml from a temporary folder; the error (or "").
struct Loaded {
  bool ok = false;
  FlyConfig config;
  std::string error, path;
};
Loaded load(const std::string& text) {
  static sinu::test::TempDir dir;  // one folder for the whole run
  Loaded l;
  l.path = dir.write("sinu.toml", text);
  l.ok = sinu::board::load_fly_config(l.path, l.config, l.error);
  return l;
}

/// The one error a file must give: "FILE:LINE: what".
void expect_error(const std::string& text, const std::string& line_and_message) {
  const Loaded l = load(text);
  EXPECT_FALSE(l.ok);
  EXPECT_EQ(l.error, l.path + ":" + line_and_message);
}

}  // namespace

TEST(FlyConfig, ShippedFileIsTheDefaults) {
  // With ShippedFileShowsEveryKey: every key is in the file, at its default.
  FlyConfig c;
  std::string error;
  ASSERT_TRUE(sinu::board::load_fly_config(kShipped, c, error)) << error;
  EXPECT_TRUE(c == FlyConfig{});
}

TEST(FlyConfig, ShippedFileShowsEveryKey) {
  const toml::table file = toml::parse_file(kShipped);
  const std::string text = sinu::test::read_file(kShipped);
  const auto keys = sinu::board::fly_config_keys();
  EXPECT_EQ(keys.size(), 47u);  // 9 imu, 5 gps, 13 navigation, 11 mavlink, 5 nmea, 2 log, 2 recording
  for (const auto& k : keys) {
    SCOPED_TRACE(k.path);
    if (k.has_default) {
      EXPECT_TRUE(file.at_path(k.path)) << "the default file lacks the key";
    } else {  // no default: shown commented out, with an example
      EXPECT_FALSE(file.at_path(k.path));
      EXPECT_NE(text.find("# " + k.path.substr(k.path.rfind('.') + 1) + " = "), std::string::npos);
    }
  }
}

// The command line writes into the same FlyConfig (cli/board_options), so
// its defaults are these; and these are the driver's own defaults.
TEST(FlyConfig, DefaultsAreTheDrivers) {
  const FlyConfig c;
  sinu::drivers::Icm20948Config from_file;
  std::string error;
  ASSERT_TRUE(sinu::board::imu_config(c.imu, from_file, error)) << error;
  const sinu::drivers::Icm20948Config driver;
  EXPECT_EQ(from_file.address, driver.address);
  EXPECT_EQ(from_file.accel_range, driver.accel_range);
  EXPECT_EQ(from_file.gyro_range, driver.gyro_range);
  EXPECT_EQ(from_file.dlpf, driver.dlpf);
  EXPECT_EQ(from_file.odr_hz, driver.odr_hz);
  EXPECT_EQ(from_file.mounting.to_body({1.0, 2.0, 3.0}), driver.mounting.to_body({1.0, 2.0, 3.0}));
}

TEST(FlyConfig, EmptyFileIsTheDefaults) {
  const Loaded l = load("# nothing set\n");
  ASSERT_TRUE(l.ok) << l.error;
  EXPECT_TRUE(l.config == FlyConfig{});
}

TEST(FlyConfig, PartialFileKeepsTheOtherDefaults) {
  const Loaded l = load(
      "[gps]\nbaud = 115200\n\n[outputs.nmea]\nenabled = true\ndevice = \"/dev/ttyAMA2\"\ntalker = \"GN\"\n"
      "[navigation]\neffects = [\"accel_scale\"]\nwithout_effects = [\"none\"]\nmag_declination_deg = -3.5\n"
      "gyro_bias_walk_scale = 10\n"
      "[imu]\nrate_hz = 100.5\naddress = 0x68\n");
  ASSERT_TRUE(l.ok) << l.error;
  FlyConfig want;
  want.gps.baud = 115200;
  want.outputs.nmea.enabled = true;
  want.outputs.nmea.device = "/dev/ttyAMA2";
  want.outputs.nmea.talker = "GN";
  want.navigation.effects = {"accel_scale"};
  want.navigation.without_effects = {"none"};
  want.navigation.mag_declination_deg = -3.5;
  want.navigation.gyro_bias_walk_scale = 10.0;
  want.imu.rate_hz = 100.5;
  want.imu.address = 0x68;
  EXPECT_TRUE(l.config == want);
}

TEST(FlyConfig, SyntaxErrorNamesLineAndColumn) {
  const Loaded l = load("[imu]\ni2c = \"/dev/i2c-1\"\nrate_hz = = 40\n");
  EXPECT_FALSE(l.ok);
  EXPECT_EQ(l.error.rfind(l.path + ":3:", 0), 0u) << l.error;
  EXPECT_NE(l.error.find(": syntax error: "), std::string::npos) << l.error;
}

TEST(FlyConfig, UnknownKey) {
  expect_error("[imu]\nadress = 0x68\n",
               "2: imu.adress: unknown key ([imu] has i2c, address, drdy_chip, drdy_line, rate_hz, accel_range_g, "
               "gyro_range_dps, dlpf, mounting)");
  expect_error("verbose = true\n",
               "1: verbose: unknown key (keys belong in the sections imu, gps, navigation, outputs.mavlink, "
               "outputs.nmea, outputs.log, recording)");
}

TEST(FlyConfig, UnknownSection) {
  expect_error("[imu]\n\n[outputs.mavlnk]\nenabled = true\n",
               "3: outputs.mavlnk: unknown section (sections: imu, gps, navigation, outputs.mavlink, outputs.nmea, "
               "outputs.log, recording)");
  expect_error("imu = 5\n", "1: imu: must be a section ([imu]), not 5");
}

TEST(FlyConfig, WrongType) {
  expect_error("[gps]\nbaud = \"9600\"\n", "2: gps.baud: must be an integer, not \"9600\"");
  expect_error("[imu]\ndlpf = 5.0\n", "2: imu.dlpf: must be an integer, not 5");
  expect_error("[imu]\nrate_hz = \"fast\"\n", "2: imu.rate_hz: must be a number, not \"fast\"");
  expect_error("[navigation]\nmagnetometer = \"yes\"\n", "2: navigation.magnetometer: must be true or false, not \"yes\"");
  expect_error("[navigation]\neffects = \"lever_arm\"\n",
               "2: navigation.effects: must be an array of strings, not \"lever_arm\"");
  expect_error("[gps]\ndevice = 7\n", "2: gps.device: must be a string, not 7");
}

TEST(FlyConfig, OutOfRange) {
  expect_error(
      "# sinu.toml\n\n[imu]\ni2c = \"/dev/i2c-1\"\n\n[gps]\nbaud = 9600\n\n[outputs.mavlink]\nenabled = true\n"
      "transport = \"udp\"\nudp_port = 70000\n",
      "12: outputs.mavlink.udp_port: must be 1..65535, not 70000");
  expect_error("[imu]\nrate_hz = 2000\n", "2: imu.rate_hz: must be 4.5..1125, not 2000");
  expect_error("[imu]\naccel_range_g = 3\n", "2: imu.accel_range_g: must be one of 2, 4, 8, 16, not 3");
  expect_error("[imu]\naddress = 0x70\n", "2: imu.address: must be one of 0x68, 0x69, not 0x70");
  expect_error("[gps]\nbaud = 9601\n",
               "2: gps.baud: must be one of 4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600, not 9601");
  expect_error("[imu]\ndrdy_line = -1\n", "2: imu.drdy_line: must be 0..65535, not -1");
}

TEST(FlyConfig, BadEnumValue) {
  expect_error("[navigation]\nmodel = \"kalman\"\n", "2: navigation.model: must be one of gm, ar, not \"kalman\"");
  expect_error("[gps]\nsetup = \"ublox\"\n", "2: gps.setup: must be one of none, ubx, ubx-valset, mtk, not \"ublox\"");
  expect_error("[outputs.nmea]\ntalker = \"GL\"\n", "2: outputs.nmea.talker: must be one of GP, GN, not \"GL\"");
  const Loaded l = load("[navigation]\neffects = [\"lever_arm\",\n  \"wind\"]\n");
  EXPECT_FALSE(l.ok);
  EXPECT_EQ(l.error.rfind(l.path + ":3: navigation.effects[1]: unknown effect \"wind\" (modelled: accel_scale, ", 0),
            0u)
      << l.error;
}

TEST(FlyConfig, MalformedValues) {
  expect_error("[imu]\nmounting = \"x,y,y\"\n",
               "2: imu.mounting: must be a signed permutation of x,y,z such as \"x,-y,-z\", not \"x,y,y\"");
  expect_error("[outputs.mavlink]\nudp_host = \"localhost\"\n",
               "2: outputs.mavlink.udp_host: must be an IPv4 address such as \"127.0.0.1\", not \"localhost\"");
  expect_error("[imu]\ni2c = \"\"\n", "2: imu.i2c: must not be empty");
}

TEST(FlyConfig, MissingRequiredValue) {
  expect_error("[outputs.nmea]\nenabled = true\n", "1: outputs.nmea.device: required when outputs.nmea.enabled = true");
  expect_error("[outputs.mavlink]\nenabled = true\ntransport = \"serial\"\n",
               "1: outputs.mavlink.serial_device: required when outputs.mavlink.transport = \"serial\"");
  expect_error("[recording]\nenabled = true\npath = \"\"\n", "3: recording.path: required when recording.enabled = true");
}

TEST(FlyConfig, ConflictsBetweenKeys) {
  expect_error("[outputs.nmea]\nenabled = true\ndevice = \"/dev/serial0\"\n",
               "3: outputs.nmea.device: is gps.device: the NMEA output needs a port of its own");
  expect_error("[outputs.nmea]\nenabled = true\ndevice = \"/dev/ttyAMA2\"\nbaud = 9600\nrate_hz = 5\n",
               "5: outputs.nmea.rate_hz: 5 Hz of RMC+GGA+GST (up to 288 bytes an epoch) needs 14400 bit/s, more "
               "than outputs.nmea.baud = 9600");
}

TEST(FlyConfig, EveryErrorInTheOrderOfTheFile) {
  const Loaded l = load("[imu]\ndlpf = 9\n[gps]\nrate_hz = 0\nbogus = 1\n[navigation]\nvehicle = \"boat\"\n");
  EXPECT_FALSE(l.ok);
  EXPECT_EQ(l.error, l.path + ":2: imu.dlpf: must be 0..7, not 9\n" + l.path +
                         ":4: gps.rate_hz: must be 0.1..25, not 0\n" + l.path +
                         ":5: gps.bogus: unknown key ([gps] has device, baud, setup, rate_hz, setup_baud)\n" + l.path +
                         ":7: navigation.vehicle: must be one of air, ground, auto, not \"boat\"");
}

TEST(FlyConfig, UnreadableFile) {
  FlyConfig c;
  std::string error;
  EXPECT_FALSE(sinu::board::load_fly_config("/nonexistent/sinu.toml", c, error));
  EXPECT_EQ(error, "/nonexistent/sinu.toml: cannot read: No such file or directory");
}
