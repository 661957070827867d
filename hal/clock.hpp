#pragma once
// Monotonic time source. Every sample that leaves the HAL carries a time from
// a Clock; all files of a dataset share this clock ("t", seconds).
#include <cstdint>

namespace sinu::hal {

/// Nanoseconds on the board's monotonic clock (CLOCK_MONOTONIC on Linux).
using TimeNs = std::int64_t;

/// Seconds, correctly rounded (a division by the exact 1e9, not a product
/// with the inexact 1e-9): the same double as reading the time back from its
/// decimal text with 9 (or, for whole microseconds, 6) decimals, so a sample
/// time is the same whether it comes from the HAL or from a dataset file.
inline constexpr double ns_to_s(TimeNs t_ns) { return static_cast<double>(t_ns) / 1e9; }

class Clock {
 public:
  virtual ~Clock() = default;
  /// Current monotonic time. Never decreases.
  virtual TimeNs now_ns() = 0;
  /// Sleep until the given monotonic time (returns at once if it has passed).
  virtual void sleep_until_ns(TimeNs t_ns) = 0;
};

}  // namespace sinu::hal
