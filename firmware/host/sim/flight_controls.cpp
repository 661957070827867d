#include "firmware/host/sim/flight_controls.hpp"


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
  return from_ + (to_ - from_) * s * s * s * (10.0 + s * (-15.0 + 6.0 * s));
}

double Ramp::rate(double t) const {
  if (duration_s_ <= 0.0 || t <= t0_s_ || t >= t0_s_ + duration_s_) return 0.0;
  const double s = (t - t0_s_) / duration_s_;
  return (to_ - from_) / duration_s_ * 30.0 * s * s * (1.0 - s) * (1.0 - s);
}

ControlValues FlightControls::at(double t) const {
  return {speed.value(t), speed.rate(t), gamma.value(t), gamma.rate(t),
          bank.value(t),  bank.rate(t),  alpha.value(t), alpha.rate(t), min_turn_speed_m_s};
}

}  // namespace sinu::sim
