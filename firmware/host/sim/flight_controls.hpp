#pragma once
// The quantities that define a flight: ground speed V, flight-path angle
// gamma, bank phi and angle of attack alpha. Each changes only by a quintic
// (minimum-jerk) ramp that starts and ends with zero rate and zero second
// derivative, so every control, its rate and its acceleration are continuous:
// the airframe's acceleration, angular rate and angular acceleration are too.
namespace sinu::sim {

/// x(t) = from + (to - from) (10 s^3 - 15 s^4 + 6 s^5), s = (t - t0) / duration in [0, 1].
class Ramp {
 public:
  void hold(double value) { from_ = to_ = value; duration_s_ = 0.0; }
  void start(double t0_s, double duration_s, double to);
  double value(double t_s) const;
  double rate(double t_s) const;  // d/dt
  double target() const { return to_; }

 private:
  double t0_s_ = 0.0, duration_s_ = 0.0, from_ = 0.0, to_ = 0.0;
};

struct ControlValues {
  double speed_m_s = 0.0, speed_rate_m_s2 = 0.0;
  double gamma_rad = 0.0, gamma_rate_rad_s = 0.0;  // flight-path angle, climb positive
  double bank_rad = 0.0, bank_rate_rad_s = 0.0;     // roll, right wing down positive
  double alpha_rad = 0.0, alpha_rate_rad_s = 0.0;   // pitch above the flight path
  double min_turn_speed_m_s = 5.0;                  // slower, no turn (airframe.hpp)
};

struct FlightControls {
  Ramp speed, gamma, bank, alpha;
  double min_turn_speed_m_s = 5.0;
  ControlValues at(double t_s) const;
};

}  // namespace sinu::sim
