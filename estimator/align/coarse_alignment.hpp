#pragma once
// Initial alignment. States: WaitingForRest (accumulating a window of
// samples; a window with too much motion restarts), Levelled (roll and pitch
// from the mean specific force, turn-on gyro bias from the mean rate;
// attitude then carried by the gyros), Aligned: heading from the magnetometer
// at rest when the site's declination is configured (position and velocity
// from the next fix, moving or not), else from the GNSS course once the speed
// is high enough. The declination (from a model such as the WMM, for the
// site) is needed because the Earth field's direction is otherwise unknown.
#include "estimator/ekf/aiding/gnss_observation.hpp"
#include "estimator/ins/imu_sample.hpp"
#include "estimator/ins/nav_state.hpp"

namespace sinu::est {

enum class AlignStatus { WaitingForRest, Levelled, Aligned };

struct AlignmentConfig {
  double level_window_s = 2.0;
  double max_accel_std_m_s2 = 0.5;    // vibration allowance of a vehicle at rest, engine running
  double max_rate_rad_s = 0.05;       // 3 deg/s: well above MEMS bias, well below any manoeuvre
  double min_course_speed_m_s = 3.0;  // course from a GNSS receiver is unreliable below walking speed
  bool mag_heading = false;           // align with the magnetometer at rest (needs the declination)
  double mag_declination_rad = 0.0;   // east of true north positive
};

struct AlignmentResult {
  NavState nav;
  Eigen::Vector3d gyro_bias_rad_s = Eigen::Vector3d::Zero();  // mean rate at rest minus Earth rate
  double gyro_bias_sigma_rad_s = 0.0;  // from the window's sample scatter (and Earth rate if unknown)
  double temp_ref_degC = 0.0;
};

class CoarseAlignment {
 public:
  void configure(const AlignmentConfig& cfg) { cfg_ = cfg; reset_window(); status_ = AlignStatus::WaitingForRest; }
  /// One IMU sample, dt since the previous one.
  void add_imu(const ImuSample& s, double dt_s);
  /// A GNSS epoch valid at t_meas_s; returns true (and fills out) when it completes the alignment.
  bool add_gnss(const GnssObservation& z, double t_now_s, AlignmentResult& out);
  AlignStatus status() const { return status_; }

 private:
  void reset_window();

  AlignmentConfig cfg_;
  AlignStatus status_ = AlignStatus::WaitingForRest;
  Eigen::Vector3d sum_f_, sum_f2_, sum_w_, sum_w2_;
  Eigen::Vector3d max_w_;
  Eigen::Vector3d sum_m_;
  long count_m_ = 0;
  bool have_mag_heading_ = false;
  double mag_heading_rad_ = 0.0;       // of the rest attitude
  double window_s_ = 0.0, sum_temp_ = 0.0;
  long count_ = 0;
  Eigen::Quaterniond q_level_ = Eigen::Quaterniond::Identity();  // at rest, yaw 0
  Eigen::Quaterniond q_now_ = Eigen::Quaterniond::Identity();    // carried by the gyros
  Eigen::Vector3d mean_rate_ = Eigen::Vector3d::Zero();
  double mean_rate_sigma_ = 0.0;
  double temp_ref_ = 0.0;
};

}  // namespace sinu::est
