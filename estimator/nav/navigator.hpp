#pragma once
// The navigation unit: prefilter -> IMU ring buffer -> alignment / strapdown
// INS + error-state EKF, with GNSS fused at its own time of validity.
//
// Delayed fusion (PX4 EKF2's delayed horizon, with compile-time buffers):
// samples wait in a fixed-size ring buffer until they are `horizon_s` older
// than the newest one; by then every GNSS epoch valid at that time (arrival
// minus latency) has arrived and sits in its own ring buffer, so it is fused
// at the first IMU instant at or after its validity time, with the state
// taken back by the (sub-sample) difference. No heap after init().
#include <array>
#include <cstdint>

#include "estimator/align/coarse_alignment.hpp"
#include "estimator/ekf/aiding/gnss_observation.hpp"
#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ekf/measurement_update.hpp"
#include "estimator/ekf/predict_accumulator.hpp"
#include "estimator/prefilter/imu_prefilter.hpp"
#include "estimator/util/ring_buffer.hpp"

namespace sinu::est {

inline constexpr std::size_t kImuBufferCapacity = 512;   // 0.5 s at 1000 Hz
inline constexpr std::size_t kGnssBufferCapacity = 32;   // 6 s of 5 Hz epochs

enum class AidingSource : std::uint8_t { GnssPosition, GnssVelocity, Magnetometer };
inline constexpr std::size_t kAidingSourceCount = 3;
inline constexpr std::array<const char*, kAidingSourceCount> kAidingSourceNames = {"gnss_position", "gnss_velocity",
                                                                                   "magnetometer"};

struct NavigatorConfig {
  SensorNoise noise = SensorNoise::defaults(NoiseModelKind::GaussMarkov);
  EffectSet effects;
  EffectTuning tuning;
  NavUncertainty initial;
  AlignmentConfig alignment;
  double horizon_s = 0.3;            // must exceed the GNSS latency
  double gate_sigma = 5.0;           // innovation gate [sigma]
  double gps_latency_s = 0.0;        // configured latency (initial value when estimated)
  Eigen::Vector3d lever_arm_b_m = Eigen::Vector3d::Zero();  // antenna minus IMU, body FRD
  bool fuse_velocity = true;
  // Magnetometer: fused when the layout has Effect::MagEarthField and the
  // sample carries a field; the field state starts from the first sample after
  // alignment. sigma covers the sensor noise and small disturbances.
  double mag_sigma_uT = 1.0;
  double mag_period_s = 0.1;          // fuse at most this often (10 Hz)
  double reset_after_rejected_s = 5.0;  // position rejected this long: fuse ungated / reset (as PX4 resets)
  double covariance_period_s = 0.1;  // covariance prediction at most this far apart (0: every sample)
  double max_imu_gap_s = 0.5;        // longer gaps are counted (and bridged)
};

struct NavOutput {
  NavState nav;
  Eigen::Matrix<double, 9, 9> P_nav;  // pos, vel, att block, as of the last covariance prediction (<= covariance_period_s old)
  std::array<double, kSensorAxes> sensor_error{}, sensor_error_sigma{};
};

struct InnovationRecord {
  double t_s = 0.0;
  AidingSource source = AidingSource::GnssPosition;
  UpdateResult result;
};

struct NavCounters {
  std::array<std::uint64_t, kAidingSourceCount> accepted{}, rejected{};
  std::uint64_t gnss_late = 0;          // arrived after the horizon had passed its time
  std::uint64_t gnss_overflow = 0;      // buffer full
  std::uint64_t imu_non_increasing = 0; // dropped: time not after the previous sample
  std::uint64_t imu_gaps = 0;
  std::uint64_t imu_invalid = 0;        // non-finite values
  std::uint64_t gnss_resets = 0;        // epochs fused ungated (or reset to) after prolonged rejection
};

class NavObserver {
 public:
  virtual ~NavObserver() = default;
  virtual void on_nav(const NavOutput& out) = 0;
  virtual void on_innovation(const InnovationRecord& rec) = 0;
};

class Navigator {
 public:
  /// Everything sized here; nothing allocates afterwards.
  void init(const NavigatorConfig& cfg, NavObserver* observer, ImuPrefilter* prefilter);
  void push_imu(const ImuSample& raw);
  void push_gnss(const GnssObservation& z);
  /// End of data: process everything still buffered.
  void flush();

  bool aligned() const { return alignment_.status() == AlignStatus::Aligned; }
  AlignStatus alignment_status() const { return alignment_.status(); }
  const NavState& nav() const { return nav_; }
  const ErrorStateFilter& filter() const { return filter_; }
  const NavCounters& counters() const { return counters_; }

 private:
  void push_filtered(const ImuSample& s);
  void process(const ImuSample& s);
  void fuse_due_gnss(double t_now, double dt, const BodyRates& now);
  void fuse_magnetometer(const ImuSample& s);
  bool fuse(AidingSource src, const Measurement& m, double t_meas);
  void reset_to_gnss(const GnssObservation& z, double dt_back);
  void emit();

  NavigatorConfig cfg_;
  NavObserver* observer_ = nullptr;
  ImuPrefilter* prefilter_ = nullptr;
  PassThroughPrefilter pass_through_;
  RingBuffer<ImuSample, kImuBufferCapacity> imu_;
  RingBuffer<GnssObservation, kGnssBufferCapacity> gnss_;
  CoarseAlignment alignment_;
  ErrorStateFilter filter_;
  NavState nav_;
  ImuSample prev_;
  bool have_prev_ = false;
  bool have_raw_ = false;
  bool mag_started_ = false;
  double last_mag_t_s_ = 0.0;
  double last_raw_t_s_ = 0.0;
  Eigen::Vector3d accel_n_ = Eigen::Vector3d::Zero();
  StateVec dx_;
  PredictAccumulator predict_;
  double last_position_accepted_t_ = 0.0;
  NavOutput out_;
  NavCounters counters_;
};

}  // namespace sinu::est
