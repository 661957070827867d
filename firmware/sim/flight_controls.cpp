#include "firmware/sim/flight_controls.hpp"

#include <cmath>
#include <numbers>

namespace sinu::sim {

void Ramp::start(double t0_s, double duration_s, double to) {
  from_ = value(t0_s);
  t0_s_ = t0_s;
  duration_s_ = duration_s;
  to_ = to;
}

double Ramp::value(double t) const {
  if (duration_s_ <= 0.0 || t >= t0_s_ + duration_s_) return to_;
  if (t <= t0_s_) return from_;
  const double s = (t - t0_s_) / duration_s_;
  return from_ + (to_ - from_) * 0.5 * (1.0 - std::cos(std::numbers::pi * s));
}

double Ramp::rate(double t) const {
  if (duration_s_ <= 0.0 || t <= t0_s_ || t >= t0_s_ + duration_s_) return 0.0;
  const double s = (t - t0_s_) / duration_s_;
  return (to_ - from_) * 0.5 * std::numbers::pi / duration_s_ * std::sin(std::numbers::pi * s);
}

ControlValues FlightControls::at(double t) const {
  return {speed.value(t), speed.rate(t), gamma.value(t), gamma.rate(t),
          bank.value(t),  bank.rate(t),  alpha.value(t), alpha.rate(t)};
}

}  // namespace sinu::sim
