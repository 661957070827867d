#include "firmware/board/outputs/nmea_output.hpp"

namespace sinu::board {

namespace {
// Solution times are IMU sample times: 8 samples of 25 ms make 0.2 s only up
// to rounding, so "due" allows a microsecond.
constexpr double kDueTolerance_s = 1e-6;
}  // namespace

NmeaOutput::NmeaOutput(hal::SerialPort& port, const NmeaOutputConfig& config)
    : port_(port), config_(config), period_s_(1.0 / config.rate_hz) {}

bool NmeaOutput::offer(const NavSolution& nav) {
  if (started_ && nav.t_s < last_t_s_) started_ = false;  // time went backwards: a new run
  last_t_s_ = nav.t_s;
  if (started_ && nav.t_s + kDueTolerance_s < due_t_s_) return true;
  // Keep the phase of the schedule unless a whole period was missed (a gap
  // in the solutions): then restart it from this solution.
  due_t_s_ = started_ && nav.t_s < due_t_s_ + period_s_ ? due_t_s_ + period_s_ : nav.t_s + period_s_;
  started_ = true;
  const std::size_t n = write_nmea_epoch(nav, config_.talker, text_);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(text_.data());
  if (port_.write({bytes, n}).status != hal::SerialStatus::Ok) {
    ++counters_.write_errors;
    return false;
  }
  ++counters_.epochs;
  counters_.bytes += n;
  return true;
}

}  // namespace sinu::board
