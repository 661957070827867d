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
#include "firmware/board/state_file.hpp"

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

  void push_imu(const est::ImuSample& sample) {
    nav_->push_imu(sample);
    if (!cfg_.state_path.empty()) save_state(false);
  }
  void push_imu(const drivers::ImuSample& sample) { push_imu(to_estimator(sample)); }
  /// The fix as a GNSS observation (sigmas from GST or DOP); false when it has no usable position.
  bool observation(const drivers::GpsFix& fix, est::GnssObservation& z) const;
  /// observation() into the navigator, and the fix's time and receiver
  /// fields kept; false when the fix had no usable position.
  bool push_fix(const drivers::GpsFix& fix);
  /// The same with its observation `z` (observation(fix), true) already made.
  void push_fix(const drivers::GpsFix& fix, const est::GnssObservation& z);
  /// End of data: processes what the navigator still holds (and saves the state file).
  void flush() {
    nav_->flush();
    if (warm_pending_) {
      warm_pending_ = false;
      state_note_ = cfg_.state_path + ": no fix with a date (RMC or ZDA) to tell the state's age by: a cold start";
      ++state_note_version_;
    }
    if (!cfg_.state_path.empty()) save_state(true);
  }
  /// What became of the state file: read, used or not and why, written or
  /// not; "" without one. For the user (stderr, summary.json).
  const std::string& state_note() const { return state_note_; }
  /// Changes whenever state_note() does (for a loop that prints it once).
  int state_note_version() const { return state_note_version_; }
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
  // The state file: the saved state until the first dated fix decides on it.
  SavedState saved_;
  bool warm_pending_ = false, state_write_failed_ = false;
  double last_state_save_t_s_ = -1e300;
  std::string state_note_;
  int state_note_version_ = 0;
  /// The first dated fix: the saved state used if young enough.
  void decide_warm_start(std::int64_t fix_utc_ms);
  /// Writes the state file when due (or now, `final`), once aligned and dated.
  void save_state(bool final);
  /// UTC [ms since 1970] at navigator time t_s, from the last dated fix (which must exist).
  std::int64_t utc_ms_at(double t_s) const;
};

/// Milliseconds since 1970-01-01 UTC of a date and a time of day.
std::int64_t utc_epoch_ms(const drivers::UtcDate& date, drivers::UtcMs time_of_day_ms);

}  // namespace sinu::board
