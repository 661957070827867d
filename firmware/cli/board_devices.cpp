#include "firmware/cli/board_devices.hpp"

#include <array>
#include <cmath>

#include "drivers/gps/gps_setup.hpp"

namespace sinu::cli {

void DeviceOptions::add_to(CLI::App& cmd) {
  cmd.add_option("--i2c", i2c, "I2C bus of the ICM-20948")->capture_default_str();
  cmd.add_option("--serial", serial, "GPS serial port")->capture_default_str();
  cmd.add_option("--baud", baud, "GPS baud rate at power-up")->capture_default_str();
  cmd.add_option("--gpio-chip", gpio_chip, "GPIO chip of the IMU data-ready line")->capture_default_str();
  cmd.add_option("--drdy-line", drdy_line, "GPIO line offset of the IMU INT pin")->capture_default_str();
  cmd.add_option("--gps-setup", gps_setup, "Configure the receiver first: none, ubx (M8), ubx-valset (M9/M10/F9), mtk")
      ->check(CLI::IsMember({"none", "ubx", "ubx-valset", "mtk"}))
      ->capture_default_str();
  cmd.add_option("--gps-rate", gps_rate_hz, "GPS fix rate to configure [Hz]")->check(CLI::Range(0.1, 25.0))->capture_default_str();
  cmd.add_option("--gps-baud", gps_baud, "Baud rate to switch the receiver to")->capture_default_str();
}

bool LinuxBoard::setup_gps(const DeviceOptions& o, std::string& error) {
  if (o.gps_setup == "none") return true;
  namespace gs = drivers::gps_setup;
  const auto period_ms = static_cast<std::uint16_t>(std::lround(1000.0 / o.gps_rate_hz));
  std::array<std::uint8_t, 64> a{}, b{};
  std::size_t na = 0, nb = 0;
  if (o.gps_setup == "ubx") {
    na = gs::ubx_cfg_rate(period_ms, a);
    nb = gs::ubx_cfg_prt_uart1(o.gps_baud, b);
  } else if (o.gps_setup == "ubx-valset") {
    na = gs::ubx_valset_rate_baud(period_ms, o.gps_baud, gs::kRam, a);
  } else {
    na = gs::pmtk220_fix_interval(period_ms, a);
    nb = gs::pmtk251_baud(o.gps_baud, b);
  }
  hal::SerialPort& port = serial_tap_ ? static_cast<hal::SerialPort&>(*serial_tap_) : serial_;
  // Rate first (understood at the old baud), then the baud change, then follow it.
  if (port.write({a.data(), na}).status != hal::SerialStatus::Ok ||
      (nb > 0 && port.write({b.data(), nb}).status != hal::SerialStatus::Ok)) {
    error = o.serial + ": GPS set-up write failed: " + serial_.last_error();
    return false;
  }
  clock_.sleep_until_ns(clock_.now_ns() + 100'000'000);  // let the receiver apply it
  if (o.gps_baud != o.baud && !port.set_baud(o.gps_baud)) {
    error = o.serial + ": " + serial_.last_error();
    return false;
  }
  return true;
}

bool LinuxBoard::open(const DeviceOptions& o, const std::string& record_path, std::string& error) {
  if (!i2c_.open(o.i2c)) return (error = i2c_.last_error()), false;
  if (!serial_.open(o.serial, o.baud)) return (error = serial_.last_error()), false;
  if (!drdy_.open(o.gpio_chip, o.drdy_line)) return (error = drdy_.last_error()), false;
  if (!record_path.empty()) {
    if (!writer_.open(record_path)) return (error = writer_.error()), false;
    recording_ = true;
    i2c_tap_ = std::make_unique<hal::rec::RecordingI2cBus>(i2c_, writer_, clock_);
    serial_tap_ = std::make_unique<hal::rec::RecordingSerialPort>(serial_, writer_, clock_);
    drdy_tap_ = std::make_unique<hal::rec::RecordingGpioEdge>(drdy_, writer_);
  }
  return setup_gps(o, error);
}

board::BoardDevices LinuxBoard::devices() {
  if (recording_) return {*drdy_tap_, *i2c_tap_, *serial_tap_, clock_};
  return {drdy_, i2c_, serial_, clock_};
}

}  // namespace sinu::cli
