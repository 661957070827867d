#pragma once
// An input line whose rising edges are events (the IMU's data-ready interrupt).
#include <cstdint>

#include "hal/clock.hpp"

namespace sinu::hal {

enum class EdgeStatus : std::uint8_t {
  Edge = 0,     // a rising edge; its time is set
  Timeout = 1,  // no edge within the timeout
  Closed = 2,   // the replay ended / the line was released
  Error = 3,
};

class GpioEdge {
 public:
  virtual ~GpioEdge() = default;
  /// Waits at most `timeout_ns` for the next rising edge; on Edge, `edge_time_ns`
  /// is when it happened on the monotonic clock (kernel timestamp, not wake-up time).
  virtual EdgeStatus wait_rising(TimeNs timeout_ns, TimeNs& edge_time_ns) = 0;
};

}  // namespace sinu::hal
