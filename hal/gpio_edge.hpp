#pragma once
// An input line whose rising edges are events (the IMU's data-ready interrupt).
#include <cstdint>

#include "hal/clock.hpp"

namespace sinu::hal {

enum class EdgeStatus : std::uint8_t {
  Edge = 0,        // a rising edge; its time is set
  Timeout = 1,     // no edge within the timeout; the time is when the wait ended
  Closed = 2,      // the replay ended / the line was released
  Error = 3,
  OtherInput = 4,  // no edge yet, but another input of the board has data (GPS bytes): read it
};

class GpioEdge {
 public:
  virtual ~GpioEdge() = default;
  /// Waits at most `timeout_ns` for the next rising edge; on Edge, `edge_time_ns`
  /// is when it happened on the monotonic clock (kernel timestamp, not wake-up
  /// time); on Timeout, when the wait gave up. A back end that also watches
  /// the board's other inputs returns OtherInput as soon as one has data, so
  /// GPS bytes are time-stamped when they arrive, not at the next edge.
  virtual EdgeStatus wait_rising(TimeNs timeout_ns, TimeNs& edge_time_ns) = 0;
};

}  // namespace sinu::hal
