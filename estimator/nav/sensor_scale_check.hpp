#pragma once
// Are the sensors' readings in the units the filter assumes? Data converted
// from elsewhere can carry the accelerometer in g, the magnetometer in mG,
// G or nT: every sample is a valid number, and the filter (a 0.98-"m/s^2"
// gravity read as an 8.8 m/s^2 bias; a field ten times the Earth's taken up
// by the hard iron) degrades without saying why. Three references are known
// here without any calibration: gravity, the World Magnetic Model's field
// strength at the first fix, and a GNSS that says the unit stands still.
//   Accelerometer: the mean |specific force| of every sample before the
//     alignment against what gravity and the GNSS's motion make it. Level
//     and steady it is gravity; in a turn the receiver's velocity turns, and
//     each sample is judged against sqrt(g^2 + a_h^2), a_h the horizontal
//     acceleration differenced from the GNSS velocity over 0.5-2 s (a level
//     turn at 60 deg of bank is 2 g: judged against gravity alone, a unit
//     restarted in it was refused for the rest of the flight). NMEA carries
//     no vertical velocity, so a pull-up is not in the reference; a loop
//     averages 1.9 g over its circle, 2.8 g at its bottom. A wrong unit is
//     0.1x (g), 3.3x (ft/s^2), 10x (cm/s^2), 100x (milli-g). Outside
//     [accel_min, accel_max] the alignment is refused: no solution is better
//     than one built on it.
//   Magnetometer: each field sample before the magnetometer states start,
//     |m| against the model's strength. A hard iron of tens of uT moves it by
//     a factor of 2 at most; a wrong unit by 10 (mG), 100 (G), 1000 (nT).
//     Outside [1 / mag_max, mag_max] the sample does not start the
//     magnetometer; it is counted and the navigation goes on without it.
//   Gyro: its scatter over the last second at each GNSS epoch before the
//     alignment that says the unit stands still while the accelerometer is
//     quiet, on the two axes across the specific force: standing still, a
//     vehicle can only turn about the vertical (a quadcopter spinning on the
//     spot at 90 deg/s scatters 0.3 rad/s about it while it speeds up), and
//     any other turn moves gravity in the accelerometer; wrong units scatter
//     every axis. A MEMS gyro at rest scatters below 0.03 rad/s (the real
//     quadcopter 0.006, the real car with its engine idling 0.018-0.028, the
//     simulator 0.0016); in deg/s it reads 57x (0.09-1.6). Its mean is no
//     test: a turn-on bias can be tens of deg/s. Refused when every judged
//     epoch for gyro_persist_s exceeds the bound (wrong units are wrong at
//     every one; a hand turning the unit for a second, whose scatter the
//     1-s average holds for ~3 s more, is not). Meanwhile the epochs do not
//     align the unit.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>

#include "estimator/earth/wgs84.hpp"
#include "estimator/nav/imu_scatter.hpp"

namespace sinu::est {

struct SensorScaleCheckConfig {
  double accel_min_ratio = 0.5;   // g reads 0.1x; a quadcopter dropping 2 m/s^2 0.8x
  double accel_max_ratio = 2.5;   // ft/s^2 reads 3.3x; the bottom of a 35-m/s, 70-m loop 2.8x
  double mag_max_ratio = 5.0;
  double tau_s = 1.0;                    // the scatter's averaging time (imu_scatter.hpp)
  double still_max_speed_m_s = 0.3;      // the GNSS says still
  double still_max_accel_std_m_s2 = 0.1; // the accelerometer says still
  double gyro_max_std_rad_s = 0.05;      // 3 deg/s of noise at rest: no MEMS gyro
  double gyro_persist_s = 5.0;           // judged epochs above it for this long
};

/// The verdicts, for the summary: NaN ratios where nothing was judged.
struct SensorScaleVerdict {
  double specific_force_over_gravity = NAN;  // mean |f| before the alignment / what gravity and the turns make it
  bool accel_refused = false;                // the alignment was refused for it
  double mean_specific_force_m_s2 = NAN, gravity_m_s2 = NAN;
  double expected_over_gravity = NAN;        // what gravity and the GNSS's horizontal turns made it, / gravity
  double field_over_model = NAN;  // the last refused field sample's |m| / the model's strength
  double model_field_uT = NAN;
  std::uint64_t mag_refused_samples = 0;  // field samples that could not start the magnetometer
  bool mag_started = false;               // a field sample passed and started it
  bool gyro_refused = false;              // the alignment was refused for the gyro's scatter at rest
  double gyro_std_at_rest_rad_s = NAN;     // judged when the GNSS and the accelerometer said still
  double accel_std_at_rest_m_s2 = NAN;
  /// The magnetometer never started, for its units.
  bool mag_refused() const { return mag_refused_samples > 0 && !mag_started; }
};

class SensorScaleCheck {
 public:
  void configure(const SensorScaleCheckConfig& cfg) {
    cfg_ = cfg;
    restart();
  }
  void restart() {
    verdict_ = {};
    sum_f_ = sum_load_ = 0.0;
    n_f_ = 0;
    load_ = 1.0;
    load_age_s_ = kLoadMaxAge_s;
    anchor_t_s_ = NAN;
    scatter_.reset();
    gyro_exceeded_since_s_ = NAN;
  }
  /// A sample before the alignment, dt since the previous one.
  void add_sample(const Eigen::Vector3d& f_m_s2, const Eigen::Vector3d& w_rad_s, double dt_s) {
    if (!f_m_s2.allFinite() || !w_rad_s.allFinite()) return;
    sum_f_ += f_m_s2.norm();
    load_age_s_ += dt_s;
    sum_load_ += load_age_s_ < kLoadMaxAge_s ? load_ : 1.0;
    ++n_f_;
    scatter_.add(f_m_s2, w_rad_s, dt_s, cfg_.tau_s);
  }
  /// The receiver's horizontal velocity (not one differenced from fixes) at
  /// its time of validity, before the alignment: the samples after it are
  /// judged against gravity and the acceleration since the velocity 0.5-2 s
  /// before (shorter differences are mostly noise; longer, a gap).
  void add_gnss_velocity(double t_s, const Eigen::Vector2d& v_ne_m_s) {
    if (!v_ne_m_s.allFinite()) return;
    const double dt = t_s - anchor_t_s_;  // NaN for the first: no difference, it only anchors
    if (dt < kMinDifference_s) return;
    if (dt <= kMaxDifference_s) {
      // Capped: a velocity glitch must not excuse a wrong unit.
      const double a_g = std::min((v_ne_m_s - anchor_v_).norm() / dt / wgs84::kStandardGravity, kMaxLoad_g);
      load_ = std::sqrt(1.0 + a_g * a_g);
      load_age_s_ = 0.0;
    }
    anchor_t_s_ = t_s;
    anchor_v_ = v_ne_m_s;
  }
  /// A GNSS epoch before the alignment, its speed (NaN: none): the gyro's
  /// scatter is judged when the GNSS and the accelerometer say still; false
  /// while it cannot be a gyro's in rad/s (the epoch must not align the
  /// unit), refused from then on once that has lasted gyro_persist_s.
  bool gyro_plausible(double t_s, double gnss_speed_m_s) {
    const double accel_std = std::sqrt(scatter_.accel_var_m2_s4());
    const double gyro_std = std::sqrt(scatter_.rate_var_across_f_rad2_s2());
    if (verdict_.gyro_refused) return false;
    if (!(gnss_speed_m_s < cfg_.still_max_speed_m_s) || !(accel_std < cfg_.still_max_accel_std_m_s2)) return true;
    verdict_.gyro_std_at_rest_rad_s = gyro_std;
    verdict_.accel_std_at_rest_m_s2 = accel_std;
    if (!(gyro_std > cfg_.gyro_max_std_rad_s)) gyro_exceeded_since_s_ = NAN;
    else if (std::isnan(gyro_exceeded_since_s_)) gyro_exceeded_since_s_ = t_s;
    verdict_.gyro_refused = t_s - gyro_exceeded_since_s_ >= cfg_.gyro_persist_s;
    return std::isnan(gyro_exceeded_since_s_);
  }
  /// At the alignment: true when the accelerometer reads gravity as gravity.
  bool accel_plausible(double gravity_m_s2) {
    if (n_f_ == 0) return true;
    verdict_.mean_specific_force_m_s2 = sum_f_ / static_cast<double>(n_f_);
    verdict_.gravity_m_s2 = gravity_m_s2;
    verdict_.expected_over_gravity = sum_load_ / static_cast<double>(n_f_);
    const double r = verdict_.mean_specific_force_m_s2 / (gravity_m_s2 * verdict_.expected_over_gravity);
    verdict_.specific_force_over_gravity = r;
    verdict_.accel_refused = !(r >= cfg_.accel_min_ratio && r <= cfg_.accel_max_ratio);
    return !verdict_.accel_refused;
  }
  /// A field sample that would start the magnetometer: true when its
  /// strength can be the Earth's (or no model strength is known).
  bool field_plausible(double norm_uT, double model_uT) {
    const bool judged = model_uT > 0.0 && std::isfinite(norm_uT);
    const double r = judged ? norm_uT / model_uT : 1.0;
    if (r <= cfg_.mag_max_ratio && r >= 1.0 / cfg_.mag_max_ratio) return verdict_.mag_started = true;
    verdict_.field_over_model = r;
    verdict_.model_field_uT = model_uT;
    ++verdict_.mag_refused_samples;
    return false;
  }
  const SensorScaleVerdict& verdict() const { return verdict_; }
  /// The alignment was refused: the accelerometer's or the gyro's units.
  bool refused() const { return verdict_.accel_refused || verdict_.gyro_refused; }

 private:
  static constexpr double kMinDifference_s = 0.5, kMaxDifference_s = 2.0;
  static constexpr double kLoadMaxAge_s = 2.0;  // a reference this old is none: gravity alone
  static constexpr double kMaxLoad_g = 4.0;  // beyond any UAV's sustained turn
  SensorScaleCheckConfig cfg_;
  SensorScaleVerdict verdict_;
  double sum_f_ = 0.0, sum_load_ = 0.0;  // |f| and its reference / gravity, summed over the samples
  double load_ = 1.0, load_age_s_ = kLoadMaxAge_s;
  double anchor_t_s_ = NAN;  // the velocity the next acceleration is differenced from
  Eigen::Vector2d anchor_v_ = Eigen::Vector2d::Zero();
  std::uint64_t n_f_ = 0;
  ImuScatter scatter_;
  double gyro_exceeded_since_s_ = NAN;  // the first of the judged epochs in a row above the bound
};

}  // namespace sinu::est
