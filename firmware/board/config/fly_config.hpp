#pragma once
// sinu fly's configuration file, /etc/sinu/sinu.toml (TOML; the shipped copy
// with every key at its default: firmware/board/package/sinu.toml). Every key
// is optional: a missing key keeps its default, which is the command line's
// (firmware/cli: board_options, board_devices, navigation_options). Strings
// with a fixed vocabulary stay strings, in the words the command line takes.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "firmware/board/config/config_key.hpp"

namespace sinu::board {

struct FlyConfig {
  struct Imu {  // ICM-20948 on I2C, data-ready on a GPIO line
    std::string i2c = "/dev/i2c-1";
    int address = 0x69;  // AD0 high, the driver's default (0x68: AD0 low)
    std::string drdy_chip = "gpiochip0";
    unsigned drdy_line = 24;
    double rate_hz = 40.0;
    int accel_range_g = 8;      // 2, 4, 8, 16
    int gyro_range_dps = 1000;  // 250, 500, 1000, 2000
    int dlpf = 5;               // 0..7
    std::string mounting = "x,-y,-z";  // body FRD axes from chip axes
    bool operator==(const Imu&) const = default;
  };
  struct Gps {  // NMEA receiver on a UART
    std::string device = "/dev/serial0";
    std::uint32_t baud = 9600;     // at power-up
    std::string setup = "none";    // none, ubx, ubx-valset, mtk
    double rate_hz = 5.0;          // fix rate to configure (with a setup)
    std::uint32_t setup_baud = 115200;  // baud to switch the receiver to (with a setup)
    bool operator==(const Gps&) const = default;
  };
  struct Navigation {
    // calib.json from `sinu calibrate`. It need not exist: then the navigator
    // runs on its built-in defaults (as `sinu replay` without --calib), and
    // fly should say so when it starts. "": never use one.
    std::string calibration = "/var/lib/sinu/calib.json";
    // A model file from `sinu diagnose --apply` (effects known from earlier
    // flights, with values); "": none.
    std::string model_file;
    // The state file (state_file.hpp): saved every few seconds; a restart in
    // the air (the companion computer rebooted) starts from it. "": none.
    std::string state_file = "/var/lib/sinu/state.json";
    std::string model = "ar";               // gm, ar
    std::vector<std::string> effects;        // effect states added to the defaults
    std::vector<std::string> without_effects;  // defaults removed ("none": all of them)
    std::string vehicle = "auto";           // auto, air, ground (vehicle_words.hpp)
    bool magnetometer = true;
    std::optional<double> mag_declination_deg;  // east +; unset: heading from the course
    double gps_latency_s = 0.05;
    double imu_latency_s = 0.0;  // the IMU's samples stamped this much late
    // calib.json's bias random walks times these (`sinu diagnose` says when a bias moved more).
    double accel_bias_walk_scale = 1.0, gyro_bias_walk_scale = 1.0;
    bool operator==(const Navigation&) const = default;
  };
  struct Mavlink {
    bool enabled = false;
    std::string transport = "udp";  // udp, serial
    std::string udp_host = "127.0.0.1";
    int udp_port = 14550;
    std::string serial_device;      // required for transport = "serial"
    std::uint32_t serial_baud = 921600;
    double rate_hz = 10.0;
    int system_id = 1;              // the vehicle's: the autopilot's system id
    // MAV_COMPONENT 197, MAV_COMP_ID_VISUAL_INERTIAL_ODOMETRY ("provides
    // position estimates"): the one id for an external position estimator.
    int component_id = 197;
    bool odometry = true;   // ODOMETRY
    bool gps_input = true;  // GPS_INPUT
    bool operator==(const Mavlink&) const = default;
  };
  struct Nmea {  // nmea_output: RMC, GGA, GST as an external GPS
    bool enabled = false;
    std::string device;  // required when enabled
    std::uint32_t baud = 115200;
    double rate_hz = 5.0;
    std::string talker = "GP";  // GP, GN
    bool operator==(const Nmea&) const = default;
  };
  struct Log {  // the navigation solution as nav.csv
    bool enabled = true;
    std::string path = "/var/lib/sinu/nav.csv";
    bool operator==(const Log&) const = default;
  };
  struct Outputs {
    Mavlink mavlink;
    Nmea nmea;
    Log log;
    bool operator==(const Outputs&) const = default;
  };
  struct Recording {  // raw HAL traffic (sinu record's format)
    bool enabled = false;
    std::string path = "/var/lib/sinu/flight.raw";
    bool operator==(const Recording&) const = default;
  };

  Imu imu;
  Gps gps;
  Navigation navigation;
  Outputs outputs;
  Recording recording;
  bool operator==(const FlyConfig&) const = default;
};

/// Reads `path` over the defaults in `out`. False, with every problem in
/// `error` (one per line: "FILE:LINE: dotted.key: what is wrong"; a TOML
/// syntax error as "FILE:LINE:COLUMN: ..."), when the file cannot be read,
/// is not TOML, or has an unknown, mistyped, out-of-range or missing value;
/// `out` is then unspecified.
bool load_fly_config(const std::string& path, FlyConfig& out, std::string& error);

/// The schema's keys (dotted paths) in order; has_default false for the ones
/// a default file leaves commented out (no default, or required only when a
/// feature is on).
std::vector<ConfigKey> fly_config_keys();

}  // namespace sinu::board
