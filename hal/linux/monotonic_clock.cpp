#include "hal/linux/monotonic_clock.hpp"

#include <cerrno>
#include <ctime>

namespace sinu::hal {

namespace {
constexpr TimeNs kNsPerS = 1'000'000'000;
}

TimeNs MonotonicClock::now_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<TimeNs>(ts.tv_sec) * kNsPerS + ts.tv_nsec;
}

void MonotonicClock::sleep_until_ns(TimeNs t_ns) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(t_ns / kNsPerS);
  ts.tv_nsec = static_cast<long>(t_ns % kNsPerS);
  // Absolute sleep: restarted after a signal without drifting.
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
  }
}

}  // namespace sinu::hal
