#include "firmware/cli/board_options.hpp"

#include <cstdio>
#include <filesystem>

#include "firmware/board/config/fly_setup.hpp"

namespace sinu::cli {

using board::FlyConfig;

void BoardOptions::add_imu(CLI::App& cmd) {
  add(cmd, "--mounting", [](FlyConfig& c) -> auto& { return c.imu.mounting; },
      "IMU mounting: body FRD axes from chip axes, e.g. x,-y,-z");
  add(cmd, "--accel-range", [](FlyConfig& c) -> auto& { return c.imu.accel_range_g; }, "Accelerometer full scale [g]")
      ->check(CLI::IsMember({2, 4, 8, 16}));
  add(cmd, "--gyro-range", [](FlyConfig& c) -> auto& { return c.imu.gyro_range_dps; }, "Gyroscope full scale [deg/s]")
      ->check(CLI::IsMember({250, 500, 1000, 2000}));
  add(cmd, "--dlpf", [](FlyConfig& c) -> auto& { return c.imu.dlpf; }, "Digital low-pass filter setting 0..7")
      ->check(CLI::Range(0, 7));
  add(cmd, "--imu-rate", [](FlyConfig& c) -> auto& { return c.imu.rate_hz; }, "IMU output data rate [Hz]")
      ->check(CLI::Range(4.5, 1125.0));
}

void BoardOptions::add_devices(CLI::App& cmd) {
  add(cmd, "--i2c", [](FlyConfig& c) -> auto& { return c.imu.i2c; }, "I2C bus of the ICM-20948");
  add(cmd, "--gpio-chip", [](FlyConfig& c) -> auto& { return c.imu.drdy_chip; }, "GPIO chip of the IMU data-ready line");
  add(cmd, "--drdy-line", [](FlyConfig& c) -> auto& { return c.imu.drdy_line; }, "GPIO line offset of the IMU INT pin");
  add(cmd, "--serial", [](FlyConfig& c) -> auto& { return c.gps.device; }, "GPS serial port");
  add(cmd, "--baud", [](FlyConfig& c) -> auto& { return c.gps.baud; }, "GPS baud rate at power-up");
  add(cmd, "--gps-setup", [](FlyConfig& c) -> auto& { return c.gps.setup; },
      "Configure the receiver first: none, ubx (M8), ubx-valset (M9/M10/F9), mtk")
      ->check(CLI::IsMember({"none", "ubx", "ubx-valset", "mtk"}));
  add(cmd, "--gps-rate", [](FlyConfig& c) -> auto& { return c.gps.rate_hz; }, "GPS fix rate to configure [Hz]")
      ->check(CLI::Range(0.1, 25.0));
  add(cmd, "--gps-baud", [](FlyConfig& c) -> auto& { return c.gps.setup_baud; }, "Baud rate to switch the receiver to");
}

void BoardOptions::apply_given(FlyConfig& config) const {
  for (const Override& o : overrides_) {
    if (o.option->count() > 0) o.apply(config);
  }
}

bool BoardOptions::load(const std::string& path, FlyConfig& cfg, std::string& error) const {
  constexpr const char* kDefault = "/etc/sinu/sinu.toml";
  cfg = {};
  std::error_code ec;
  const std::string file = !path.empty() ? path : std::filesystem::exists(kDefault, ec) ? kDefault : "";
  if (!file.empty() && !board::load_fly_config(file, cfg, error)) return false;
  if (file.empty()) std::fprintf(stderr, "sinu: no %s: the built-in defaults (those of the shipped sinu.toml)\n", kDefault);
  apply_given(cfg);
  return true;
}

bool BoardOptions::given(const std::string& name) const {
  for (const Override& o : overrides_) {
    if (o.option->check_name(name)) return o.option->count() > 0;
  }
  return false;
}

bool BoardOptions::imu_config(drivers::Icm20948Config& out, std::string& error) const {
  return board::imu_config(values.imu, out, error);
}

}  // namespace sinu::cli
