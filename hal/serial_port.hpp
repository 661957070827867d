#pragma once
// Serial port interface: raw 8N1 bytes, no line discipline.
#include <cstddef>
#include <cstdint>
#include <span>

#include "hal/clock.hpp"

namespace sinu::hal {

enum class SerialStatus : std::uint8_t {
  Ok = 0,       // `bytes` transferred (a read may return 0 bytes when the timeout expired)
  Closed = 1,   // end of stream: the device went away or the replay ended
  Error = 2,    // an I/O error (see the back end's last_error())
};

struct SerialResult {
  SerialStatus status = SerialStatus::Ok;
  std::size_t bytes = 0;
  TimeNs time_ns = 0;  // monotonic time the bytes were taken from the driver (reads)
};

class SerialPort {
 public:
  virtual ~SerialPort() = default;
  /// Changes the line speed (bits per second); false if the back end cannot.
  virtual bool set_baud(std::uint32_t baud) = 0;
  /// Reads what is available, waiting at most `timeout_ns` for the first byte
  /// (0: do not wait). Never blocks longer than the timeout.
  virtual SerialResult read(std::span<std::uint8_t> out, TimeNs timeout_ns) = 0;
  /// Writes all bytes (blocking until the driver took them).
  virtual SerialResult write(std::span<const std::uint8_t> bytes) = 0;
};

}  // namespace sinu::hal
