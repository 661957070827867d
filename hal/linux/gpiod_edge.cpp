#include "hal/linux/gpiod_edge.hpp"

#include <gpiod.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <poll.h>

namespace sinu::hal {

namespace {
constexpr const char* kConsumer = "sinu-imu-drdy";
constexpr TimeNs kNsPerS = 1'000'000'000;

TimeNs monotonic_now_ns() {
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now);
  return TimeNs{now.tv_sec} * kNsPerS + now.tv_nsec;
}
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
  const int event_fd = gpiod_line_event_get_fd(line_);
  pollfd fds[2] = {{event_fd, POLLIN, 0}, {other_fd_, POLLIN, 0}};
  const timespec timeout{static_cast<time_t>(timeout_ns / kNsPerS), static_cast<long>(timeout_ns % kNsPerS)};
  const int r = ::ppoll(fds, other_fd_ >= 0 ? 2 : 1, &timeout, nullptr);  // event_fd < 0 fails the read below
  if (r == 0 || (r < 0 && errno == EINTR)) {
    edge_time_ns = monotonic_now_ns();
    return EdgeStatus::Timeout;
  }
  if (r > 0 && !(fds[0].revents & POLLIN) && fds[1].revents) {
    // A port that hung up or failed would wake us forever: stop watching it
    // (the loop still drains it after every edge and sees it closed).
    if (!(fds[1].revents & POLLIN)) other_fd_ = -1;
    return EdgeStatus::OtherInput;
  }
  gpiod_line_event event{};
  if (r < 0 || gpiod_line_event_read(line_, &event) < 0) {
    edge_time_ns = monotonic_now_ns();
    last_error_ = std::string("gpiod: ") + std::strerror(errno);
    return EdgeStatus::Error;
  }
  if (event.event_type != GPIOD_LINE_EVENT_RISING_EDGE) {  // not asked for; treated as no edge
    edge_time_ns = monotonic_now_ns();
    return EdgeStatus::Timeout;
  }
  edge_time_ns = static_cast<TimeNs>(event.ts.tv_sec) * kNsPerS + event.ts.tv_nsec;
  return EdgeStatus::Edge;
}

}  // namespace sinu::hal
