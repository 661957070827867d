#pragma once
// The navigation unit: a NavUnitConfig made into a navigator (calibration
// read, denoiser and state layout chosen, everything allocated), then fed
// driver samples and GPS fixes one by one. The board's fly loop, the replay
// of a dataset or a recording and the diagnosis all build it here, the same
// way; what differs is only where samples come from and where outputs go.
//
// The state layout comes from the configuration alone: the magnetometer's
// states are reserved and switched on by the first field sample (as PX4's
// EKF2 does), so nothing has to read the data ahead.
#include <memory>
#include <string>

#include "drivers/gps/gps_fix.hpp"
#include "drivers/imu/icm20948.hpp"
#include "estimator/nav/navigator.hpp"
#include "estimator/prefilter/imu_prefilter.hpp"
#include "firmware/board/nav_solution.hpp"
#include "firmware/board/nav_unit_config.hpp"

namespace sinu::board {

/// The one conversion of a driver sample (HAL time in ns, arrays) into the
/// estimator's (seconds, Eigen): the time as a dataset's t reads back.
est::ImuSample to_estimator(const drivers::ImuSample& sample);

/// The IMU full scales the driver configures, as the clipping screen needs them.
void full_scales(const drivers::Icm20948Config& imu, double& accel_m_s2, double& gyro_rad_s);

class NavUnit {
 public:
  /// Reads the calibration, builds the denoiser and the navigator; all the
  /// unit's allocation happens here. False with `error` (naming the file and
  /// key at fault) otherwise.
  bool init(const NavUnitConfig& config, est::NavObserver* observer, std::string& error);

  void push_imu(const est::ImuSample& sample) { nav_->push_imu(sample); }
  void push_imu(const drivers::ImuSample& sample) { nav_->push_imu(to_estimator(sample)); }
  /// The fix as a GNSS observation (sigmas from GST or DOP); false when it has no usable position.
  bool observation(const drivers::GpsFix& fix, est::GnssObservation& z) const;
  void push_gnss(const est::GnssObservation& z) { nav_->push_gnss(z); }
  /// observation() and push_gnss(); false when the fix had no usable position.
  bool push_fix(const drivers::GpsFix& fix);
  /// End of data: processes what the navigator still holds.
  void flush() { nav_->flush(); }
  /// What the outputs need of a navigator output: the solution in output
  /// units, its UTC (from the last fix's time of validity), the receiver's
  /// geoid separation, satellites and HDOP.
  void solution(const est::NavOutput& out, NavSolution& sol) const;

  const est::Navigator& navigator() const { return *nav_; }
  const NavUnitConfig& config() const { return cfg_; }
  const DenoiserSpec& denoiser() const { return denoiser_; }
  /// The time of validity of a fix that arrived at `arrival_s` (configured latency).
  double validity_time(double arrival_s) const { return arrival_s - cfg_.gps_latency_s; }
  double configured_gps_latency_s() const { return cfg_.gps_latency_s; }

 private:
  NavUnitConfig cfg_;
  DenoiserSpec denoiser_;
  std::unique_ptr<est::ImuPrefilter> prefilter_;
  std::unique_ptr<est::ImuPrefilter> correction_;  // calib.json's six_position, in front of prefilter_
  std::unique_ptr<est::Navigator> nav_;
  // The last fix with a position, for the solution's time and receiver fields.
  bool have_fix_ = false, fix_has_utc_ = false;
  std::int64_t fix_utc_ms_ = 0;
  double fix_arrival_s_ = 0.0, geoid_sep_m_ = 0.0, hdop_ = 99.99;
  int satellites_ = 0;
};

/// Milliseconds since 1970-01-01 UTC of a date and a time of day.
std::int64_t utc_epoch_ms(const drivers::UtcDate& date, drivers::UtcMs time_of_day_ms);

}  // namespace sinu::board
