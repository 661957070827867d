#include "firmware/board/recording_devices.hpp"

namespace sinu::board {

bool RecordingDevices::start(const std::string& path, const BoardDevices& plain, std::string& error) {
  if (!writer_.open(path)) {
    error = writer_.error();
    return false;
  }
  recording_ = true;
  i2c_ = std::make_unique<hal::rec::RecordingI2cBus>(plain.i2c, writer_, plain.clock);
  gps_ = std::make_unique<hal::rec::RecordingSerialPort>(plain.gps, writer_, plain.clock);
  drdy_ = std::make_unique<hal::rec::RecordingGpioEdge>(plain.drdy, writer_);
  return true;
}

BoardDevices RecordingDevices::devices(const BoardDevices& plain) {
  if (!recording_) return plain;
  return {*drdy_, *i2c_, *gps_, plain.clock};
}

}  // namespace sinu::board
