#include "hal/linux/gpiod_edge.hpp"

#include <gpiod.h>

#include <cerrno>
#include <cstring>
#include <ctime>

namespace sinu::hal {

namespace {
constexpr const char* kConsumer = "sinu-imu-drdy";
constexpr TimeNs kNsPerS = 1'000'000'000;
}  // namespace

GpiodEdge::~GpiodEdge() {
  if (line_) gpiod_line_release(line_);
  if (chip_) gpiod_chip_close(chip_);
}

bool GpiodEdge::open(const std::string& chip, unsigned line_offset) {
  chip_ = gpiod_chip_open_lookup(chip.c_str());
  if (!chip_) {
    last_error_ = chip + ": " + std::strerror(errno);
    return false;
  }
  line_ = gpiod_chip_get_line(chip_, line_offset);
  if (!line_ || gpiod_line_request_rising_edge_events(line_, kConsumer) < 0) {
    last_error_ = chip + " line " + std::to_string(line_offset) + ": " + std::strerror(errno);
    line_ = nullptr;
    return false;
  }
  return true;
}

EdgeStatus GpiodEdge::wait_rising(TimeNs timeout_ns, TimeNs& edge_time_ns) {
  if (!line_) return EdgeStatus::Closed;
  const timespec timeout{static_cast<time_t>(timeout_ns / kNsPerS), static_cast<long>(timeout_ns % kNsPerS)};
  const int r = gpiod_line_event_wait(line_, &timeout);
  if (r == 0) return EdgeStatus::Timeout;
  gpiod_line_event event{};
  if (r < 0 || gpiod_line_event_read(line_, &event) < 0) {
    last_error_ = std::string("gpiod: ") + std::strerror(errno);
    return EdgeStatus::Error;
  }
  if (event.event_type != GPIOD_LINE_EVENT_RISING_EDGE) return EdgeStatus::Timeout;
  edge_time_ns = static_cast<TimeNs>(event.ts.tv_sec) * kNsPerS + event.ts.tv_nsec;
  return EdgeStatus::Edge;
}

}  // namespace sinu::hal
