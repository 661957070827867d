#pragma once
// Linux back end of hal::GpioEdge: libgpiod 1.6 (v1 API) line events.
// The event timestamp is the kernel's (taken in the interrupt handler):
// CLOCK_MONOTONIC on kernels >= 5.7, which is the clock MonotonicClock reads.
#include <string>

#include "hal/gpio_edge.hpp"

struct gpiod_chip;
struct gpiod_line;

namespace sinu::hal {

class GpiodEdge final : public GpioEdge {
 public:
  GpiodEdge() = default;
  ~GpiodEdge() override;
  GpiodEdge(const GpiodEdge&) = delete;
  GpiodEdge& operator=(const GpiodEdge&) = delete;
  /// Requests rising-edge events on `line_offset` of `chip` ("gpiochip0" or a path).
  bool open(const std::string& chip, unsigned line_offset);
  EdgeStatus wait_rising(TimeNs timeout_ns, TimeNs& edge_time_ns) override;
  /// Also returns (OtherInput) when `fd` is readable: the GPS serial port, so
  /// its bytes are read, and time-stamped, as they arrive. -1: edges only.
  void also_wake_on(int fd) { other_fd_ = fd; }
  const std::string& last_error() const { return last_error_; }

 private:
  gpiod_chip* chip_ = nullptr;
  gpiod_line* line_ = nullptr;
  int other_fd_ = -1;
  std::string last_error_;
};

}  // namespace sinu::hal
