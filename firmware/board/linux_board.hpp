#pragma once
// The companion computer's sensors on Linux: the ICM-20948 on /dev/i2c-N, its
// data-ready line through libgpiod, the GPS on a tty (configured first when
// asked), with an optional raw recording of all traffic. The data-ready wait
// also wakes on GPS bytes, so they are time-stamped as they arrive.
#include <string>

#include "firmware/board/board_loop.hpp"
#include "firmware/board/config/fly_config.hpp"
#include "firmware/board/recording_devices.hpp"
#include "hal/linux/gpiod_edge.hpp"
#include "hal/linux/i2c_dev.hpp"
#include "hal/linux/monotonic_clock.hpp"
#include "hal/linux/termios_serial.hpp"

namespace sinu::board {

class LinuxBoard {
 public:
  /// Opens everything; `record_path` empty: no recording. On false, `error` says why.
  bool open(const FlyConfig::Imu& imu, const FlyConfig::Gps& gps, const std::string& record_path, std::string& error);
  BoardDevices devices();
  hal::rec::RecordingWriter* writer() { return recording_.writer(); }
  hal::MonotonicClock& clock() { return clock_; }

 private:
  bool setup_gps(const FlyConfig::Gps& gps, std::string& error);

  hal::MonotonicClock clock_;
  hal::LinuxI2cBus i2c_;
  hal::TermiosSerialPort serial_;
  hal::GpiodEdge drdy_;
  RecordingDevices recording_;
};

}  // namespace sinu::board
