#pragma once
// The navigation unit: screen -> prefilter -> IMU ring buffer -> alignment /
// strapdown INS + error-state EKF, with GNSS fused at its own time of
// validity, the magnetometer when it has a sample, and the health of it all.
//
// Delayed fusion (PX4 EKF2's delayed horizon, with compile-time buffers):
// samples wait in a fixed-size ring buffer until they are `horizon_s` older
// than the newest one; by then every GNSS epoch valid at that time (arrival
// minus latency) has arrived and sits in its own ring buffer, so it is fused
// at the first IMU instant at or after its validity time, with the state
// taken back by the (sub-sample) difference. No heap after init().
//
// Faults are survived, counted and flagged (nav_health.hpp): dropped
// samples (NaN, time not increasing), clipping (process noise of the clipped
// axes widened, their biases frozen), gaps (propagated over the true interval
// with the unknown motion's noise), GNSS rejected for too long (reset, see
// gnss_recovery.hpp), sensor timeouts.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "estimator/align/coarse_alignment.hpp"
#include "estimator/ekf/aiding/gnss_observation.hpp"
#include "estimator/ekf/aiding/nonholonomic/nonholonomic.hpp"
#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ekf/measurement_update.hpp"
#include "estimator/ekf/predict_accumulator.hpp"
#include "estimator/nav/course_hold.hpp"
#include "estimator/nav/gnss_recovery.hpp"
#include "estimator/nav/heading_check.hpp"
#include "estimator/nav/imu_screen.hpp"
#include "estimator/nav/sensor_scale_check.hpp"
#include "estimator/nav/nav_health.hpp"
#include "estimator/nav/noise_adapter.hpp"
#include "estimator/nav/sample_period.hpp"
#include "estimator/nav/stillness.hpp"
#include "estimator/nav/vehicle_detector.hpp"
#include "estimator/nav/warm_start.hpp"
#include "estimator/nav/velocity_history.hpp"
#include "estimator/nav/vertical_check.hpp"
#include "estimator/prefilter/imu_prefilter.hpp"
#include "estimator/util/ring_buffer.hpp"

namespace sinu::est {

inline constexpr std::size_t kImuBufferCapacity = 512;   // 0.5 s at 1000 Hz
inline constexpr std::size_t kGnssBufferCapacity = 32;   // 6 s of 5 Hz epochs
// The learnt latency's floor: a fix valid up to this long after it arrived
// (IMU stamps that late); the epoch waits in its buffer until then.
inline constexpr double kMinGpsLatency_s = -0.3;

/// What the unit is mounted in: a ground vehicle adds the non-holonomic
/// constraint (no sideways, no vertical velocity in the body frame) and
/// zero-velocity updates at stops; Auto finds out (vehicle_detector.hpp).
enum class VehicleKind : std::uint8_t { Air, Ground, Auto };

struct NavigatorConfig {
  SensorNoise noise = SensorNoise::defaults(NoiseModelKind::GaussMarkov);
  EffectSet effects;
  EffectTuning tuning;
  NavUncertainty initial;
  AlignmentConfig alignment;
  RecoveryConfig recovery;
  // The INS's vd against the GNSS heights' rate (vertical_check.hpp): when it
  // has run away, vd is reset to the rate (its sigma and vertical_reset_sigma_m_s)
  // and the accelerometer bias along gravity widened by vertical_bias_widen_m_s2.
  VerticalCheckConfig vertical;
  double vertical_reset_sigma_m_s = 0.5;
  double vertical_bias_widen_m_s2 = 0.5;
  // The heading against the magnetometer (heading_check.hpp): when its
  // innovations stay on one side on a straight leg (turning slower than
  // heading_check_max_turn_rad_s), the gyro bias about the vertical is
  // widened by heading_bias_widen_rad_s.
  HeadingCheckConfig heading;
  double heading_bias_widen_rad_s = 0.02;
  double heading_check_max_turn_rad_s = 0.052;  // 3 deg/s: judged on straight legs
  double course_min_speed_m_s = 3.0;            // the GNSS course's rate from this speed on
  ImuScreenConfig screen;            // full scales: clipping
  SensorScaleCheckConfig scale_check;  // units: gravity and the Earth field as references
  // The delayed horizon: at least this, and it grows with the latency
  // estimate (latency + horizon_margin_s, up to max_horizon_s and what the IMU
  // buffer holds), so a receiver slower than assumed is still fused at its
  // time of validity; the outputs are that much older.
  double horizon_s = 0.3;
  double horizon_margin_s = 0.1;
  double max_horizon_s = 1.2;        // the GPS latency the vocabulary allows is 1 s
  double gate_sigma = 5.0;           // innovation gate [sigma]
  double gps_latency_s = 0.0;        // configured latency (initial value when estimated)
  // The IMU's samples are stamped this much after the instant they describe
  // (a sensor's filter delay, a driver's read latency, a recorder's clock
  // offset): every sample is taken back by it, so the outputs are stamped
  // at the instant they describe. A learnt GPS latency below zero says so.
  double imu_latency_s = 0.0;
  Eigen::Vector3d lever_arm_b_m = Eigen::Vector3d::Zero();  // antenna minus IMU, body FRD
  bool fuse_velocity = true;
  VehicleKind vehicle = VehicleKind::Air;
  VehicleDetectorConfig vehicle_detector;  // with VehicleKind::Auto
  CourseHoldConfig course_hold;
  // A bracket's yaw found from the body velocity: its error beyond the
  // heading's at the moment (which it shares; the evidence is a minute's average)
  double vehicle_mount_sigma_rad = 0.035;
  NonholonomicConfig nonholonomic;
  double nonholonomic_period_s = 0.1;
  double nonholonomic_min_speed_m_s = 1.0;
  // Zero-velocity updates while standing still (stillness.hpp, and the GNSS
  // speed below still_max_gnss_speed_m_s when there is one): for a ground
  // vehicle, which stops often and for long; an aircraft's few seconds on
  // the ground add little (measured on simulated flights: the heading at
  // take-off is no better, the tilt slightly overconfident).
  bool zero_velocity_in_air = false;
  StillnessConfig stillness;
  double still_max_gnss_speed_m_s = 0.2;
  double zero_velocity_sigma_m_s = 0.02;
  double zero_velocity_period_s = 0.2;
  // Magnetometer: its states (Earth field, hard iron, and soft iron when in
  // `effects`) are reserved and switched on by the first field sample after
  // alignment; sigma covers the sensor noise and small disturbances.
  bool use_mag = true;
  double mag_sigma_uT = 1.0;          // initial value when adapted
  // The declination's uncertainty as a prior on the Earth field's direction:
  // the World Magnetic Model's 0.3-0.5 deg, local anomalies, residual soft iron.
  double declination_sigma_rad = 0.035;
  // The model's field strength and inclination, fused when the field states
  // start (aiding/field_model): the model's 0.2 uT, crustal anomalies and a
  // magnetometer's scale error of up to ~10 % (4-6 uT); the inclination's
  // anomalies and axes scaled differently (uav_log171 measures 2.8 deg less).
  double field_model_sigma_uT = 5.0;
  double inclination_sigma_rad = 0.05;
  // Noise the data do not state, learnt from the innovations (noise_adapter.hpp):
  // GNSS velocity (NMEA has no accuracy for it; the initial value is the
  // observation's sigma) and the magnetometer.
  NoiseAdapterConfig gnss_velocity_noise{true, 60.0, 0.02, 2.0};
  NoiseAdapterConfig mag_noise{true, 60.0, 0.1, 5.0};
  // A GNSS position sigma the receiver does not state (no GST: DOP x UERE,
  // or a fixed guess without DOP) times a learnt factor, horizontal and
  // vertical: a receiver 5x better or 4x worse than the guess. An epoch
  // without GST from a receiver that sent one within stated_sigma_hold_s
  // takes that one instead (uav_log171's u-blox skips 17 of 959).
  NoiseAdapterConfig gnss_position_scale{true, 60.0, 0.2, 4.0};
  // A stated sigma (GST) is honoured as the fix's total error; its split into
  // white and correlated (EffectTuning::gps_bias_variance_fraction) is a
  // guess, so a factor on the white part is learnt, horizontal and vertical:
  // from 1 (the split as tuned) up to all of the stated variance white (the
  // cap follows from the fraction). An independent simulator's white-only
  // receiver with an honest GST was otherwise rejected thousands of times.
  NoiseAdapterConfig gnss_white_scale{true, 60.0, 1.0, 1e9};
  double stated_sigma_hold_s = 5.0;
  double mag_period_s = 0.1;          // fuse at most this often (10 Hz)
  // A magnetometer rejected this long while the GNSS velocity vouches for the
  // attitude is disturbed by a new field of the vehicle's own (motor currents
  // after take-off, a payload switched on): the hard iron is re-anchored to
  // what the sensor reads now (PX4 EKF2 realigns its field in flight likewise).
  double mag_reanchor_after_s = 1.0;
  double covariance_period_s = 0.1;  // covariance prediction at most this far apart (0: every sample)
  // The gyro's scale factor is calibrated nowhere (the bench session measures
  // noise, the six-position calibration the accelerometer), and consumer
  // MEMS gyros leave the factory within 1-3 %. Without gyro_scale states its
  // error s w is in no model: in a 120-deg/s yaw spin 2.5 % is 3 deg/s, and a
  // filter sure of its yaw to 0.2 deg turned the magnetometer's misfit into
  // a gyro bias of 7 deg/s (the independent simulator's gyro-scale
  // quadcopter, lost for its last 4 minutes). Attitude noise of density
  // c |w| per body axis covers it: 0.002 already kept that flight, 0.01 cost
  // the real quadcopter's position-only replay 0.9 deg; 0.005 sqrt(s) (0.5 %
  // over the ~1 s the aiding needs to see the attitude) is the middle
  // (docs/experiments.md, "A gyro whose scale nobody calibrated"). Off while
  // gyro_scale is carried.
  double gyro_scale_noise_rt_s = 0.005;
  // Faults.
  double clip_error_fraction = 0.5;   // 1 sigma of the unknown true value of a clipped axis, x full scale
  double clip_hold_s = 10.0;          // a clipped axis's biases stay frozen this long after it clipped
  // Vibration: the white noise the processed samples show, from their
  // sample-to-sample differences (a vehicle's own motion changes little in
  // one sample; noise and vibration change a lot): var(x_k - x_k-1) / 2 per
  // sample, averaged over vibration_tau_s, is a density floor for the model.
  bool vibration_noise = true;
  double vibration_tau_s = 2.0;
  double gap_periods = 3.5;           // an interval longer than this many sample periods is a gap
  double gap_accel_sigma_m_s2 = 1.0;  // unknown acceleration and rate during a gap, on top of
  double gap_rate_sigma_rad_s = 0.02; // half the change across it
  double latency_freeze_after_gap_s = 2.0;  // the GPS latency is not learnt this long after a gap
  // The receiver's correlated error is not learnt this long after the
  // solution was disturbed (disturbed()): the fixes' misfit then is the
  // solution's own, and a slow state that took it would hold it for minutes.
  double gps_bias_hold_after_disturbance_s = 10.0;
  // Disturbed too when a fix arrives while the solution's horizontal position
  // sigma exceeds this many times the fix's.
  double disturbed_position_sigmas = 3.0;
  // Heading observability: while the heading is uncertain (sigma above
  // yaw_freeze_sigma_rad) and the horizontal acceleration is below
  // yaw_observable_accel_m_s2 (at rest, steady flight), no update may move it:
  // at rest the accelerometer's noise, read as horizontal specific force,
  // would otherwise make the filter grow confident of a heading it cannot see.
  // Not while the magnetometer holds the heading: with the yaw frozen, its
  // updates turned the field's direction instead, and the declination's prior
  // was lost (uav_log171 at rest: its sigma 2.0 -> 3.0 deg in 30 s).
  double yaw_freeze_sigma_rad = 0.05;
  double yaw_observable_accel_m_s2 = 0.3;
  double yaw_gyro_vertical_cos = 0.7;  // gyro axes within 45 deg of vertical are frozen with the yaw
  double gnss_timeout_s = 2.0;
  double mag_timeout_s = 1.0;
};

struct NavOutput {
  NavState nav;
  Eigen::Matrix<double, 9, 9> P_nav;  // pos, vel, att block, as of the last covariance prediction (<= covariance_period_s old)
  Eigen::Vector3d angular_rate_b_rad_s = Eigen::Vector3d::Zero();  // the sample's rate, sensor errors removed (zero at alignment)
  std::array<double, kSensorAxes> sensor_error{}, sensor_error_sigma{};
  std::uint32_t flags = 0;            // nav_flag bits: state now, events since the previous output
  // Largest component test ratio of the latest update of each source (PX4 style: > 1 rejects).
  std::array<double, kAidingSourceCount> test_ratio{};
};

struct InnovationRecord {
  double t_s = 0.0;
  AidingSource source = AidingSource::GnssPosition;
  UpdateResult result;
};

class NavObserver {
 public:
  virtual ~NavObserver() = default;
  virtual void on_nav(const NavOutput& out) = 0;
  virtual void on_innovation(const InnovationRecord& rec) = 0;
};

/// The magnetometer's states: reserved, and switched on by its first field sample.
inline constexpr Effect kMagEffects[] = {Effect::MagEarthField, Effect::MagHardIron, Effect::MagSoftIron,
                                         Effect::MagMisalign};

class Navigator {
 public:
  /// Everything sized here; nothing allocates afterwards.
  void init(const NavigatorConfig& cfg, NavObserver* observer, ImuPrefilter* prefilter);
  void push_imu(const ImuSample& raw);
  void push_gnss(const GnssObservation& z);
  /// End of data: process everything still buffered.
  void flush();

  bool aligned() const { return alignment_.status() == AlignStatus::Aligned && !scale_check_.refused(); }
  AlignStatus alignment_status() const { return alignment_.status(); }
  const NavState& nav() const { return nav_; }
  const ErrorStateFilter& filter() const { return filter_; }
  const NavCounters& counters() const { return counters_; }
  /// Whether the ground-vehicle constraints are in use now (configured, or detected).
  bool ground_vehicle() const {
    return cfg_.vehicle == VehicleKind::Ground ||
           (cfg_.vehicle == VehicleKind::Auto && vehicle_.guess() == VehicleGuess::Ground);
  }
  /// The vehicle's axes for the constraint: the contract's (y, z), or as the detector found a unit on a bracket.
  VehicleAxes nhc_axes() const { return cfg_.vehicle == VehicleKind::Auto ? vehicle_.axes() : VehicleAxes{}; }
  const VehicleDetector& vehicle_detector() const { return vehicle_; }
  /// How the alignment went (valid once aligned): the heading's source, the declination used.
  const AlignmentResult& alignment_result() const { return alignment_result_; }
  /// Whether the accelerometer and magnetometer read in the assumed units (sensor_scale_check.hpp).
  const SensorScaleVerdict& scale_verdict() const { return scale_check_.verdict(); }
  const NavigatorConfig& config() const { return cfg_; }
  /// The noise sigmas in use now (learnt, or as configured).
  double gnss_velocity_sigma_m_s() const { return vel_noise_.sigma(); }
  double mag_sigma_uT() const { return mag_noise_.sigma(); }
  /// The factor on unstated GNSS position sigmas (1 while every fix had GST).
  Eigen::Vector2d gnss_position_scale() const { return {pos_scale_h_.sigma(), pos_scale_v_.sigma()}; }
  /// The learnt factor on the white part of stated (GST) sigmas, horizontal and vertical.
  Eigen::Vector2d gnss_white_scale() const { return {white_h_.sigma(), white_v_.sigma()}; }
  /// What this navigator has learnt, for a restart (warm_start.hpp): given once aligned.
  WarmStart warm_state() const;
  /// A restart: `saved`, `age_s` old, becomes the priors of the effects this
  /// navigator carries (not the turn-on biases: warm_start.hpp) and its
  /// learnt noise levels; the alignment keeps the receiver's correlated
  /// error where it is tighter than the fix's level, and the magnetometer's
  /// iron where the field at rest says it has not moved. Only before the
  /// alignment: false after.
  bool warm_start(const WarmStart& saved, double age_s);
  /// The restart's state in use (given = false without one).
  const WarmStart& warm() const { return warm_; }

 private:
  /// A time that never was: "not since".
  static constexpr double kNever = -1e300;

  void push_filtered(ImuSample s);
  void process(const ImuSample& s);
  void align(const ImuSample& s, double dt);
  /// Process noise for what the IMU model leaves out: clipping, gaps, the gyro scale.
  void widen_for_imu_errors(const ImuSample& s, double dt);
  void fuse_due_gnss(double t_now, double dt, const BodyRates& now);
  void fuse_magnetometer(const ImuSample& s, const BodyRates& now);
  void fuse_vehicle_constraints(const ImuSample& s, const BodyRates& now);
  bool fuse(AidingSource src, const Measurement& m, double t_meas);
  /// The longest horizon the configuration and the IMU buffer allow.
  double horizon_limit_s() const {
    const double period_s = period_.seconds();
    const double buffer_s = period_s > 0.0 ? static_cast<double>(kImuBufferCapacity - 2) * period_s : cfg_.horizon_s;
    return std::max(cfg_.horizon_s, std::min(cfg_.max_horizon_s, buffer_s));
  }
  /// A field sample within mag_timeout_s (the magnetometer states on).
  bool mag_live(double t_s) const { return mag_started_ && t_s - last_mag_sample_t_s_ <= cfg_.mag_timeout_s; }
  /// The magnetometer holds the heading: live, with the field's direction known (the declination prior).
  bool mag_sees_heading(double t_s) const { return mag_live(t_s) && std::isfinite(alignment_result_.declination_rad); }
  /// The largest latency the longest horizon can serve (two IMU periods of margin).
  double max_gps_latency_s() const { return std::max(0.0, horizon_limit_s() - 2.0 * period_.seconds() - 0.01); }
  void recover(RecoveryAction action, const GnssObservation& z, double dt_back, double t_meas);
  /// Effect e's states into frozen_: no update moves them (until frozen_ is next rebuilt).
  void freeze(Effect e);
  /// The solution's own error has outgrown the fixes' (a reset to GNSS, an
  /// IMU gap in motion, the first fix after an outage, a position widened
  /// by its misfit): the receiver's correlated error is held for
  /// gps_bias_hold_after_disturbance_s. On a real quadcopter with a generous
  /// receiver (GST 4.6x its error) it took 2 m of a 3-s IMU gap's drift from
  /// one fix and held the solution 4 m off for minutes.
  void disturbed(double t_s);
  /// Within gps_bias_hold_after_disturbance_s of the latest disturbed().
  bool holding_gps_bias(double t_s) const { return t_s - disturbed_t_s_ < cfg_.gps_bias_hold_after_disturbance_s; }
  /// Before any reset: P brought to now, the first reset's time kept.
  void begin_reset(double t_meas);
  /// The fix's height to the vertical check; resets vd when it has run away.
  void check_vertical(const GnssObservation& z, double t_meas);
  /// The last field update's misfit to the heading check; widens the gyro bias
  /// about the vertical when the misfit is the filter's.
  void check_heading(double t_meas);
  /// After a course alignment: turns the solution to the in-motion alignment's
  /// yaw when that is informative and contradicts it (coarse_alignment.hpp).
  void check_course(const GnssObservation& z, double t_now, double dt_back);
  /// Widens the gyro bias about the vertical by heading_bias_widen_rad_s (P at now).
  void release_gyro_bias_about_vertical();
  /// Sets the horizontal velocity from fix z (its sigma), the vertical's sigma kept as given (NMEA has none).
  void seed_velocity_on_fix(const GnssObservation& z, double sigma_vd_m_s);
  /// Sets the position (and its covariance) from fix z, taken at dt_back before now.
  void seed_position_on_fix(const GnssObservation& z, double dt_back);
  /// The mean acceleration over the GNSS velocity's lag behind its fix (the
  /// gps_velocity_latency state), up to the fix's time of validity.
  Eigen::Vector3d velocity_lag_accel(double t_meas) const;
  /// The GNSS course's rate (moving, a fix within 1 s), else the INS heading's [rad/s].
  double turn_rate_rad_s(double t_s) const;
  void learn_position_noise(const GnssObservation& z, double t_meas);
  Eigen::Vector3d white_scale(const GnssObservation& z) const;
  /// The white-share learner's settings: the configured ones, capped at "all white".
  NoiseAdapterConfig white_scale_config() const;
  /// A restart's saved magnetometer iron, offered to the alignment at rest
  /// (warm_start.hpp checked_by_the_field), and carried when it aligned on it.
  void offer_saved_iron();
  void keep_saved_iron();
  /// At a rest alignment, after seed_gyro_bias: the state file's turn-on
  /// biases, kept (the accelerometer's as its prior) where the rest measures
  /// them again (warm_start.hpp checked_by_the_rest); says which in
  /// alignment_result_.saved_biases.
  void keep_saved_biases(const Eigen::Vector3d& f_b, double sigma_along_m_s2);
  /// The restart's priors of the effects checked by the field (given where saved and carried).
  std::array<EffectPrior, kEffectCount> saved_iron() const;
  void update_health(double t_now, double dt);
  void emit();

  NavigatorConfig cfg_;
  NavObserver* observer_ = nullptr;
  ImuPrefilter* prefilter_ = nullptr;
  PassThroughPrefilter pass_through_;
  ImuScreen screen_;
  RingBuffer<ImuSample, kImuBufferCapacity> imu_;
  RingBuffer<GnssObservation, kGnssBufferCapacity> gnss_;
  CoarseAlignment alignment_;
  SensorScaleCheck scale_check_;
  AlignmentResult alignment_result_;
  ErrorStateFilter filter_;
  // The filter as the alignment seeded it, kept while the course check runs:
  // where the course proves wrong, what was learnt under it is dropped and
  // the filter restarts from here (check_course).
  ErrorStateFilter filter_at_alignment_;
  double course_contradicted_since_s_ = -1e300;  // the course check's contradiction began then (-1e300: none)
  GnssRecovery recovery_;
  VerticalCheck vertical_;
  HeadingCheck heading_;
  CourseHold course_hold_;
  // The turn rate the heading check is judged by: the GNSS course's (smoothed
  // over 1 s) while moving, else the INS heading's between field updates.
  double course_rad_ = 0.0, course_t_s_ = -1e300, course_rate_rad_s_ = 0.0;
  double heading_yaw_rad_ = 0.0, heading_yaw_t_s_ = -1e300, yaw_rate_rad_s_ = 0.0;
  NavState nav_;
  ImuSample prev_;
  bool have_prev_ = false;
  bool mag_started_ = false;
  double mag_reject_since_s_ = -1.0;
  double last_mag_fused_t_s_ = 0.0, last_mag_sample_t_s_ = 0.0;
  Eigen::Vector3d accel_n_ = Eigen::Vector3d::Zero();
  VelocityHistory velocity_history_;  // for a GNSS velocity older than its fix
  StateVec dx_;
  PredictAccumulator predict_;
  // Raw-stream bookkeeping (before the prefilter's delay).
  double last_raw_t_s_ = 0.0;
  SamplePeriod raw_period_;
  bool have_raw_ = false;
  std::array<double, kSensorAxes> clip_until_t_s_{};     // prefilter outputs up to here carry a raw clip
  std::array<double, kSensorAxes> last_clip_t_s_{};      // latest processed clipped sample, per axis
  std::array<int, kSensorAxes> clip_run_{};              // consecutive clipped intervals, per axis
  SamplePeriod period_;                                  // nominal interval of the processed stream
  double last_gap_t_s_ = -1e300;                         // end of the latest IMU gap
  double disturbed_t_s_ = -1e300;                        // the latest disturbed()
  double horizon_now_s_ = 0.0;                           // the horizon in use (grows with the latency estimate)
  double horizontal_accel_m_s2_ = 0.0;                   // smoothed (1 s) horizontal specific force, NED
  double accel_diff_var_ = 0.0, gyro_diff_var_ = 0.0;    // mean squared sample-to-sample differences
  StateMask frozen_;
  NoiseAdapter vel_noise_, mag_noise_, pos_scale_h_, pos_scale_v_, white_h_, white_v_;
  Stillness stillness_;
  VehicleDetector vehicle_;
  double last_gnss_speed_m_s_ = 1e9, last_zupt_t_s_ = 0.0, last_nhc_t_s_ = 0.0;
  bool still_now_ = false;
  bool vel_noise_started_ = false;
  UpdateResult last_result_;
  double last_vel_update_t_s_ = 0.0, last_pos_scale_t_s_ = 0.0, last_stated_t_s_ = 0.0;
  Eigen::Vector3d last_stated_sigma_ned_m_ = Eigen::Vector3d::Zero();
  // Health.
  std::uint32_t events_ = 0, state_flags_ = 0;
  std::array<double, kAidingSourceCount> test_ratio_{};
  double last_gnss_pos_t_s_ = 0.0;
  bool in_timeout_ = false;
  NavOutput out_;
  NavCounters counters_;
  WarmStart warm_;  // a restart's saved state, aged (warm_start)
};

}  // namespace sinu::est
