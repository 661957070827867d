#pragma once
// Levelling at rest: while the IMU is still (rates below a threshold, the
// specific force steady) its window grows, and every sample refines roll and
// pitch (the mean specific force is -C_bn g), the turn-on gyro bias (the mean
// rate, less Earth rate once the heading is known), the magnetometer mean and
// the temperature. A window must last `window_s` before it counts; the first
// motion ends it, and the estimate of the whole rest period is kept. The
// longer the rest, the less the gyro-carried attitude drifts afterwards.
//
// Motion is a short-term mean (exponential, `motion_tau_s`) of the rate above
// max_rate_rad_s, or of the specific force or rate leaving the window's mean by
// more than its noise allows: vibration averages out, the onset of a gentle
// acceleration does not. The samples just before the onset are already
// touched by it, so the estimate kept is the window as it was at least
// `motion_tau_s` earlier.
//
// A steady acceleration without rotation is, to an accelerometer, a tilt: a
// take-off run at 2.8 m/s^2 held for the window's 2 s looks like a rest
// 16 deg nose-up with 0.4 m/s^2 of bias along gravity. Only another sensor
// can tell (coarse_alignment.hpp: the GNSS speed), and restore() or forget()
// then undo the windows since.
#include "estimator/ins/imu_sample.hpp"

#include <Eigen/Geometry>

namespace sinu::est {

struct RestConfig {
  double window_s = 2.0;
  double max_accel_std_m_s2 = 0.5;  // vibration allowance of a vehicle at rest, engine running
  double max_rate_rad_s = 0.05;     // 3 deg/s: well above MEMS bias, well below any manoeuvre
  double motion_tau_s = 0.5;
  double motion_accel_m_s2 = 0.05;  // short-term mean off the window mean by this (+ its noise): motion
  double motion_rate_rad_s = 0.005;
};

struct RestEstimate {
  Eigen::Quaterniond q_level = Eigen::Quaterniond::Identity();  // roll and pitch, yaw 0
  Eigen::Vector3d mean_specific_force_b_m_s2 = Eigen::Vector3d::Zero();
  double specific_force_sigma_m_s2 = 0.0;       // standard error of that mean
  Eigen::Vector3d mean_rate_b_rad_s = Eigen::Vector3d::Zero();  // turn-on gyro bias + Earth rate
  double mean_rate_sigma_rad_s = 0.0;
  Eigen::Vector3d mean_mag_b_uT = Eigen::Vector3d::Zero();
  bool has_mag = false;
  double temp_degC = 0.0;
  double duration_s = 0.0;
};

class RestLevelling {
 public:
  void configure(const RestConfig& cfg);
  /// One sample, dt since the previous one.
  void add(const ImuSample& s, double dt_s);
  /// A rest window of at least window_s has been seen.
  bool has_estimate() const { return has_estimate_; }
  /// The latest sample belonged to the current (valid) rest window.
  bool at_rest() const { return at_rest_; }
  const RestEstimate& estimate() const { return est_; }
  /// Rest windows seen so far (one more each time a window reaches window_s).
  long windows() const { return windows_; }
  /// Back to an earlier estimate (the windows since were no rest); a new window starts.
  void restore(const RestEstimate& e);
  /// No rest seen after all; a new window starts.
  void forget();

 private:
  struct Sums {
    Eigen::Vector3d f = Eigen::Vector3d::Zero(), f2 = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero(),
                    w2 = Eigen::Vector3d::Zero(), m = Eigen::Vector3d::Zero();
    double temp = 0.0, window_s = 0.0;
    long count = 0, count_m = 0;
  };
  void restart();
  bool moving(const ImuSample& s, double dt_s);
  void estimate_from(const Sums& sums);

  RestConfig cfg_;
  Sums now_, snapshot_, older_;  // the window now, and as it was one and two snapshot periods ago
  double since_snapshot_s_ = 0.0;
  Eigen::Vector3d ema_f_ = Eigen::Vector3d::Zero(), ema_w_ = Eigen::Vector3d::Zero();
  bool have_ema_ = false;
  bool has_estimate_ = false, at_rest_ = false;
  long windows_ = 0;
  RestEstimate est_;
};

}  // namespace sinu::est
