#pragma once
// Are the sensors' readings in the units the filter assumes? Data converted
// from elsewhere can carry the accelerometer in g, the magnetometer in mG,
// G or nT: every sample is a valid number, and the filter (a 0.98-"m/s^2"
// gravity read as an 8.8 m/s^2 bias; a field ten times the Earth's taken up
// by the hard iron) degrades without saying why. Two references are known
// here without any calibration: gravity, and the World Magnetic Model's
// field strength at the first fix.
//   Accelerometer: the mean |specific force| of every sample before the
//     alignment against normal gravity. Vehicles average ~1 g (a level turn at
//     45 deg of bank 1.41 g, vibration adds a little); a wrong unit is 0.1x
//     (g), 3.3x (ft/s^2), 100x (milli-g). Outside [accel_min, accel_max] the
//     alignment is refused: no solution is better than one built on it.
//   Magnetometer: each field sample before the magnetometer states start,
//     |m| against the model's strength. A hard iron of tens of uT moves it by
//     a factor of 2 at most; a wrong unit by 10 (mG), 100 (G), 1000 (nT).
//     Outside [1 / mag_max, mag_max] the sample does not start the
//     magnetometer; it is counted and the navigation goes on without it.
#include <cmath>
#include <cstdint>

namespace sinu::est {

struct SensorScaleCheckConfig {
  double accel_min_ratio = 0.7;
  double accel_max_ratio = 1.5;
  double mag_max_ratio = 5.0;
};

/// The verdicts, for the summary: NaN ratios where nothing was judged.
struct SensorScaleVerdict {
  double specific_force_over_gravity = NAN;  // mean |f| before the alignment / normal gravity
  bool accel_refused = false;                // the alignment was refused for it
  double mean_specific_force_m_s2 = NAN, gravity_m_s2 = NAN;
  double field_over_model = NAN;  // the last refused field sample's |m| / the model's strength
  double model_field_uT = NAN;
  std::uint64_t mag_refused_samples = 0;  // field samples that could not start the magnetometer
};

class SensorScaleCheck {
 public:
  void configure(const SensorScaleCheckConfig& cfg) {
    cfg_ = cfg;
    restart();
  }
  void restart() {
    verdict_ = {};
    sum_f_ = 0.0;
    n_f_ = 0;
  }
  /// A sample's specific force before the alignment [m/s^2].
  void add_specific_force(double norm_m_s2) {
    if (!std::isfinite(norm_m_s2)) return;
    sum_f_ += norm_m_s2;
    ++n_f_;
  }
  /// At the alignment: true when the accelerometer reads gravity as gravity.
  bool accel_plausible(double gravity_m_s2) {
    if (n_f_ == 0) return true;
    verdict_.mean_specific_force_m_s2 = sum_f_ / static_cast<double>(n_f_);
    verdict_.gravity_m_s2 = gravity_m_s2;
    const double r = verdict_.mean_specific_force_m_s2 / gravity_m_s2;
    verdict_.specific_force_over_gravity = r;
    verdict_.accel_refused = !(r >= cfg_.accel_min_ratio && r <= cfg_.accel_max_ratio);
    return !verdict_.accel_refused;
  }
  /// A field sample that would start the magnetometer: true when its
  /// strength can be the Earth's (or no model strength is known).
  bool field_plausible(double norm_uT, double model_uT) {
    if (!(model_uT > 0.0) || !std::isfinite(norm_uT)) return true;
    const double r = norm_uT / model_uT;
    if (r <= cfg_.mag_max_ratio && r >= 1.0 / cfg_.mag_max_ratio) return true;
    verdict_.field_over_model = r;
    verdict_.model_field_uT = model_uT;
    ++verdict_.mag_refused_samples;
    return false;
  }
  const SensorScaleVerdict& verdict() const { return verdict_; }

 private:
  SensorScaleCheckConfig cfg_;
  SensorScaleVerdict verdict_;
  double sum_f_ = 0.0;
  std::uint64_t n_f_ = 0;
};

}  // namespace sinu::est
