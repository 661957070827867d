#pragma once
// The companion computer's sensors on Linux, opened from command-line
// options (`sinu record`, `sinu fly`), with optional GPS set-up and an
// optional raw recording of all traffic.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "firmware/board/board_loop.hpp"
#include "hal/linux/gpiod_edge.hpp"
#include "hal/linux/i2c_dev.hpp"
#include "hal/linux/monotonic_clock.hpp"
#include "hal/linux/termios_serial.hpp"
#include "hal/recording/recording_taps.hpp"

namespace sinu::cli {

struct DeviceOptions {
  std::string i2c = "/dev/i2c-1";
  std::string serial = "/dev/serial0";
  std::uint32_t baud = 9600;
  std::string gpio_chip = "gpiochip0";
  unsigned drdy_line = 24;
  std::string gps_setup = "none";  // none, ubx, ubx-valset, mtk
  double gps_rate_hz = 5.0;
  std::uint32_t gps_baud = 115200;
  void add_to(CLI::App& cmd);
};

/// Open Linux devices, optionally wrapped in recording taps.
class LinuxBoard {
 public:
  /// Opens everything; `record_path` empty: no recording. On false, `error` says why.
  bool open(const DeviceOptions& o, const std::string& record_path, std::string& error);
  board::BoardDevices devices();
  hal::rec::RecordingWriter* writer() { return recording_ ? &writer_ : nullptr; }

 private:
  bool setup_gps(const DeviceOptions& o, std::string& error);

  hal::MonotonicClock clock_;
  hal::LinuxI2cBus i2c_;
  hal::TermiosSerialPort serial_;
  hal::GpiodEdge drdy_;
  hal::rec::RecordingWriter writer_;
  bool recording_ = false;
  std::unique_ptr<hal::rec::RecordingI2cBus> i2c_tap_;
  std::unique_ptr<hal::rec::RecordingSerialPort> serial_tap_;
  std::unique_ptr<hal::rec::RecordingGpioEdge> drdy_tap_;
};

}  // namespace sinu::cli
