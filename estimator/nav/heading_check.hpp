#pragma once
// The heading against the magnetometer. A gyro bias that shifts about the
// vertical (a knock, a temperature step, a rate sensor's g-dependence in a
// long turn) turns the heading at its rate; a calibrated bias walk says it
// cannot happen, so the bias learns it over minutes while the magnetometer's
// innovations grow on one side. The noise learner then took that misfit for
// noise (the field sigma rose to its 5-uT ceiling) and the heading ran 49 deg
// away under a claimed 0.3-6 deg (2 deg/s about z at 400 s into a flight;
// reset by the GNSS recovery 12 minutes later). PX4 EKF2 lets its biases move
// far faster (gyro_bias_p_noise 1e-3 rad/s^2) and has no such learner.
//
// The check: each update's innovation seen as a heading error (projected on
// the reading's change for a turn of the heading, in rad, with its sigma), and
// a running mean over `time_constant_s` of it and of its normalised value.
// White innovations keep the normalised mean within sqrt(a / (2 - a)) of zero
// (a = 1 - exp(-dt / tau)); the check fires when it stays beyond `sigmas` times
// that and the mean heading misfit beyond `min_misfit_rad` for `persist_s`:
// then the misfit is the filter's, not the sensor's, and the gyro bias about
// the vertical is let move. The navigator feeds it on straight legs only (a
// field model that is not quite right misfits by an amount that follows the
// heading, and in a turn the filter lags that one-signed). A field that
// moves in the body (motor currents) mostly moves along the body's vertical,
// which a turn of the heading does not. The field's noise is still learnt
// meanwhile: not learning it from a one-sided misfit changed little here
// and cost the real quadcopter 0.14 deg (its motor currents are such a
// misfit, and noise to the filter).
#include <cmath>

namespace sinu::est {

struct HeadingCheckConfig {
  double time_constant_s = 5.0;
  double sigmas = 5.0;
  double min_misfit_rad = 0.0175;  // 1 deg
  double persist_s = 2.0;
  double hold_off_s = 20.0;  // after firing: the widened bias needs time to learn it
};

class HeadingCheck {
 public:
  void configure(const HeadingCheckConfig& cfg) {
    cfg_ = cfg;
    restart();
  }
  void restart() {
    last_t_s_ = kNever;
    mean_rad_ = mean_z_ = white_var_ = 0.0;
    weight_ = 0.0;
    since_s_ = kNever;
  }
  /// One update's heading misfit [rad] and its sigma. True when the misfit is the filter's.
  bool push(double t_s, double misfit_rad, double sigma_rad) {
    if (!std::isfinite(t_s) || !std::isfinite(misfit_rad) || !(sigma_rad > 0.0)) return false;
    if (last_t_s_ != kNever && t_s <= last_t_s_) restart();
    const double dt = last_t_s_ == kNever ? 0.0 : t_s - last_t_s_;
    last_t_s_ = t_s;
    if (t_s < hold_until_s_) return false;
    // A running mean at first (weight_ samples), then exponential.
    const double decay = std::exp(-dt / cfg_.time_constant_s);
    weight_ = weight_ * decay + 1.0;
    const double a = 1.0 / weight_;
    mean_rad_ += a * (misfit_rad - mean_rad_);
    mean_z_ += a * (misfit_rad / sigma_rad - mean_z_);
    // The spread of the normalised mean for white input: sum of squared weights.
    white_var_ = (1.0 - a) * (1.0 - a) * white_var_ + a * a;
    const bool off = weight_ > 5.0 && std::abs(mean_z_) > cfg_.sigmas * std::sqrt(white_var_) &&
                     std::abs(mean_rad_) > cfg_.min_misfit_rad;
    if (!off) {
      since_s_ = kNever;
      return false;
    }
    if (since_s_ == kNever) since_s_ = t_s;
    if (t_s - since_s_ < cfg_.persist_s) return false;
    restart();
    hold_until_s_ = t_s + cfg_.hold_off_s;
    return true;
  }

 private:
  static constexpr double kNever = -1e300;
  HeadingCheckConfig cfg_;
  double last_t_s_ = kNever, since_s_ = kNever, hold_until_s_ = kNever;
  double mean_rad_ = 0.0, mean_z_ = 0.0, white_var_ = 0.0, weight_ = 0.0;
};

}  // namespace sinu::est
