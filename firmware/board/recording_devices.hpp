#pragma once
// A board's devices behind recording taps: with a recording started, every
// I2C transfer, data-ready edge and GPS byte the loop sees also goes to the
// raw HAL recording (`sinu fly --record`, on Linux and on the emulated board).
#include <memory>
#include <string>

#include "firmware/board/board_loop.hpp"
#include "hal/recording/recording_taps.hpp"

namespace sinu::board {

class RecordingDevices {
 public:
  /// Starts recording the traffic of `plain` (which must outlive this) to
  /// `path`. False with `error` if the file cannot be written.
  bool start(const std::string& path, const BoardDevices& plain, std::string& error);
  /// The taps while recording, else `plain`.
  BoardDevices devices(const BoardDevices& plain);
  /// The recording's writer (for syncs and the close), nullptr when not recording.
  hal::rec::RecordingWriter* writer() { return recording_ ? &writer_ : nullptr; }

 private:
  hal::rec::RecordingWriter writer_;
  bool recording_ = false;
  std::unique_ptr<hal::rec::RecordingI2cBus> i2c_;
  std::unique_ptr<hal::rec::RecordingSerialPort> gps_;
  std::unique_ptr<hal::rec::RecordingGpioEdge> drdy_;
};

}  // namespace sinu::board
