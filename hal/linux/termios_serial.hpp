#pragma once
// Linux back end of hal::SerialPort: a tty in raw 8N1 mode (no echo, no
// canonical lines, no CR/LF translation, no flow control), read with poll().
#include <string>

#include "hal/serial_port.hpp"

namespace sinu::hal {

class TermiosSerialPort final : public SerialPort {
 public:
  TermiosSerialPort() = default;
  ~TermiosSerialPort() override;
  TermiosSerialPort(const TermiosSerialPort&) = delete;
  TermiosSerialPort& operator=(const TermiosSerialPort&) = delete;
  /// Opens `device` (e.g. /dev/ttyAMA0 or a pty) at `baud` in raw 8N1 mode.
  bool open(const std::string& device, std::uint32_t baud);
  /// Takes over an already-open tty descriptor (the port closes it).
  bool adopt(int fd, std::uint32_t baud);
  bool set_baud(std::uint32_t baud) override;
  SerialResult read(std::span<std::uint8_t> out, TimeNs timeout_ns) override;
  SerialResult write(std::span<const std::uint8_t> bytes) override;
  const std::string& last_error() const { return last_error_; }
  /// The descriptor, for a wait on several inputs (GpiodEdge::also_wake_on); -1 if closed.
  int fd() const { return fd_; }
  /// Time-stamps reads with `clock` instead of CLOCK_MONOTONIC (an emulated
  /// board's clock); nullptr: back to CLOCK_MONOTONIC.
  void stamp_with(Clock* clock) { stamp_clock_ = clock; }

 private:
  SerialResult fail(const char* what);

  int fd_ = -1;
  Clock* stamp_clock_ = nullptr;
  std::string last_error_;
};

}  // namespace sinu::hal
