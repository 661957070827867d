#pragma once
// Replay back end of hal::Clock: time is whatever the replayed recording says.
// sleep_until_ns() jumps forward instead of waiting, so replays run flat out.
#include "hal/clock.hpp"

namespace sinu::hal {

class ManualClock final : public Clock {
 public:
  explicit ManualClock(TimeNs start_ns = 0) : now_ns_(start_ns) {}
  TimeNs now_ns() override { return now_ns_; }
  void sleep_until_ns(TimeNs t_ns) override { advance_to_ns(t_ns); }
  /// Moves time forward; a request to go back is ignored (the clock is monotonic).
  void advance_to_ns(TimeNs t_ns) {
    if (t_ns > now_ns_) now_ns_ = t_ns;
  }

 private:
  TimeNs now_ns_;
};

}  // namespace sinu::hal
