#include "firmware/board/config/fly_config.hpp"

#include <arpa/inet.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "drivers/imu/axis_map.hpp"
#include "estimator/ekf/state_layout.hpp"
#include "firmware/board/config/toml_reader.hpp"
#include "firmware/board/config/vehicle_words.hpp"
#include "firmware/board/outputs/nmea_sentences.hpp"

namespace sinu::board {

namespace {

// The line speeds the termios back end sets (hal/linux/termios_serial).
constexpr std::array<std::int64_t, 9> kBauds = {4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600};
constexpr std::array<std::int64_t, 2> kImuAddresses = {0x68, 0x69};  // AD0 low, high
constexpr std::array<std::int64_t, 4> kAccelRanges = {2, 4, 8, 16};
constexpr std::array<std::int64_t, 4> kGyroRanges = {250, 500, 1000, 2000};
constexpr std::array<std::string_view, 4> kGpsSetups = {"none", "ubx", "ubx-valset", "mtk"};
constexpr std::array<std::string_view, 2> kModels = {"gm", "ar"};
constexpr std::array<std::string_view, 2> kTransports = {"udp", "serial"};
constexpr std::array<std::string_view, 2> kTalkers = {"GP", "GN"};

std::string not_empty(const std::string& v) { return v.empty() ? "must not be empty" : ""; }

std::string mounting_check(const std::string& v) {
  if (drivers::AxisMap::parse(v)) return "";
  return "must be a signed permutation of x,y,z such as \"x,-y,-z\", not \"" + v + "\"";
}

std::string effect_check(const std::string& v) {
  est::Effect e{};
  if (est::effect_from_name(v.c_str(), v.size(), e)) return "";
  std::string names;
  for (const char* n : est::kEffectNames) names += std::string(names.empty() ? "" : ", ") + n;
  return "unknown effect \"" + v + "\" (modelled: " + names + ")";
}

std::string without_effect_check(const std::string& v) { return v == "none" ? "" : effect_check(v); }

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string ipv4_check(const std::string& v) {
  in_addr a{};
  return inet_pton(AF_INET, v.c_str(), &a) == 1 ? "" : "must be an IPv4 address such as \"127.0.0.1\", not \"" + v + "\"";
}

void read_sections(TomlReader& r, FlyConfig& c) {
  TomlSection imu = r.section("imu");
  imu.text("i2c", c.imu.i2c, not_empty);
  imu.integer_of("address", c.imu.address, kImuAddresses, true);
  imu.text("drdy_chip", c.imu.drdy_chip, not_empty);
  imu.integer("drdy_line", c.imu.drdy_line, 0, 65535);
  imu.number("rate_hz", c.imu.rate_hz, 4.5, 1125.0);  // the ICM-20948's output data rates
  imu.integer_of("accel_range_g", c.imu.accel_range_g, kAccelRanges);
  imu.integer_of("gyro_range_dps", c.imu.gyro_range_dps, kGyroRanges);
  imu.integer("dlpf", c.imu.dlpf, 0, 7);
  imu.text("mounting", c.imu.mounting, mounting_check);

  TomlSection gps = r.section("gps");
  gps.text("device", c.gps.device, not_empty);
  gps.integer_of("baud", c.gps.baud, kBauds);
  gps.choice("setup", c.gps.setup, kGpsSetups);
  gps.number("rate_hz", c.gps.rate_hz, 0.1, 25.0);
  gps.integer_of("setup_baud", c.gps.setup_baud, kBauds);

  TomlSection nav = r.section("navigation");
  nav.text("calibration", c.navigation.calibration);
  nav.text("model_file", c.navigation.model_file);
  nav.text("state_file", c.navigation.state_file);
  nav.choice("model", c.navigation.model, kModels);
  nav.text_list("effects", c.navigation.effects, effect_check);
  nav.text_list("without_effects", c.navigation.without_effects, without_effect_check);
  nav.choice("vehicle", c.navigation.vehicle, kVehicleWords);
  nav.flag("magnetometer", c.navigation.magnetometer);
  nav.optional_number("mag_declination_deg", c.navigation.mag_declination_deg, -180.0, 180.0);
  nav.number("gps_latency_s", c.navigation.gps_latency_s, 0.0, 1.0);
  nav.number("imu_latency_s", c.navigation.imu_latency_s, 0.0, 1.0);
  nav.number("accel_bias_walk_scale", c.navigation.accel_bias_walk_scale, 0.01, 1000.0);
  nav.number("gyro_bias_walk_scale", c.navigation.gyro_bias_walk_scale, 0.01, 1000.0);

  FlyConfig::Mavlink& m = c.outputs.mavlink;
  TomlSection mav = r.section("outputs.mavlink");
  mav.flag("enabled", m.enabled);
  mav.choice("transport", m.transport, kTransports);
  mav.text("udp_host", m.udp_host, ipv4_check);
  mav.integer("udp_port", m.udp_port, 1, 65535);
  mav.optional_text("serial_device", m.serial_device);
  mav.integer_of("serial_baud", m.serial_baud, kBauds);
  mav.number("rate_hz", m.rate_hz, 0.1, 50.0);
  mav.integer("system_id", m.system_id, 1, 255);
  mav.integer("component_id", m.component_id, 1, 255);  // 0 is MAV_COMP_ID_ALL, not a sender
  mav.flag("odometry", m.odometry);
  mav.flag("gps_input", m.gps_input);

  FlyConfig::Nmea& n = c.outputs.nmea;
  TomlSection nmea = r.section("outputs.nmea");
  nmea.flag("enabled", n.enabled);
  nmea.optional_text("device", n.device);
  nmea.integer_of("baud", n.baud, kBauds);
  nmea.number("rate_hz", n.rate_hz, 0.1, 50.0);
  nmea.choice("talker", n.talker, kTalkers);

  TomlSection log = r.section("outputs.log");
  log.flag("enabled", c.outputs.log.enabled);
  log.text("path", c.outputs.log.path);

  TomlSection rec = r.section("recording");
  rec.flag("enabled", c.recording.enabled);
  rec.text("path", c.recording.path);

  // What a key alone cannot say: values required by a feature, and ports in
  // use twice.
  if (m.enabled && m.transport == "serial") {
    if (m.serial_device.empty()) mav.fail("serial_device", "required when outputs.mavlink.transport = \"serial\"");
    else if (m.serial_device == c.gps.device) mav.fail("serial_device", "is gps.device: MAVLink needs a port of its own");
  }
  if (n.enabled) {
    if (n.device.empty()) nmea.fail("device", "required when outputs.nmea.enabled = true");
    else if (n.device == c.gps.device) nmea.fail("device", "is gps.device: the NMEA output needs a port of its own");
    else if (m.enabled && m.transport == "serial" && n.device == m.serial_device)
      nmea.fail("device", "is outputs.mavlink.serial_device: the NMEA output needs a port of its own");
    // A UART that cannot carry the epochs backs up and blocks the writer.
    const double bits_s = n.rate_hz * static_cast<double>(kNmeaEpochMax) * 10.0;  // 8N1: 10 bits a byte
    if (bits_s > static_cast<double>(n.baud))
      nmea.fail("rate_hz", number_text(n.rate_hz) + " Hz of RMC+GGA+GST (up to " +
                               std::to_string(kNmeaEpochMax) + " bytes an epoch) needs " +
                               number_text(bits_s) + " bit/s, more than outputs.nmea.baud = " +
                               std::to_string(n.baud));
  }
  if (c.outputs.log.enabled && c.outputs.log.path.empty())
    log.fail("path", "required when outputs.log.enabled = true");
  if (c.recording.enabled && c.recording.path.empty()) rec.fail("path", "required when recording.enabled = true");
}

}  // namespace

bool load_fly_config(const std::string& path, FlyConfig& out, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = path + ": cannot read: " + std::strerror(errno);
    return false;
  }
  std::ostringstream text;
  text << in.rdbuf();
  toml::table root;
  try {
    root = toml::parse(text.str(), path);
  } catch (const toml::parse_error& e) {
    error = path + ":" + std::to_string(e.source().begin.line) + ":" + std::to_string(e.source().begin.column) +
            ": syntax error: " + std::string(e.description());
    return false;
  }
  TomlReader reader(path, root);
  read_sections(reader, out);
  reader.check_unknown();
  if (!reader.ok()) error = reader.errors();
  return reader.ok();
}

std::vector<ConfigKey> fly_config_keys() {
  const toml::table empty;
  TomlReader reader("", empty);
  FlyConfig defaults;
  read_sections(reader, defaults);
  return reader.keys();
}

}  // namespace sinu::board
