#pragma once
// Linux back end of hal::Clock: CLOCK_MONOTONIC, immune to NTP steps.
#include "hal/clock.hpp"

namespace sinu::hal {

class MonotonicClock final : public Clock {
 public:
  TimeNs now_ns() override;
  void sleep_until_ns(TimeNs t_ns) override;
};

}  // namespace sinu::hal
