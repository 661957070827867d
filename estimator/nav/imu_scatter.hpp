#pragma once
// The IMU's recent mean and scatter: exponential means of the specific force
// and the rate over ~tau_s, and of their squared deviations (the variance
// per axis, averaged over the three; for the rate also across the mean
// specific force alone: a vehicle that stands still can only turn about the
// vertical). What "standing still" (stillness.hpp) and "a gyro in the wrong
// units" (sensor_scale_check.hpp) are judged on.
#include <Eigen/Core>
#include <algorithm>

namespace sinu::est {

class ImuScatter {
 public:
  void reset() {
    have_ = false;
    var_f_ = var_w_ = var_w_across_ = 0.0;
  }
  /// One sample, dt since the previous one (> 0), averaged over tau_s;
  /// false for the first, which only starts the means.
  bool add(const Eigen::Vector3d& f_m_s2, const Eigen::Vector3d& w_rad_s, double dt_s, double tau_s) {
    if (!have_) {
      mean_f_ = f_m_s2;
      mean_w_ = w_rad_s;
      var_f_ = var_w_ = var_w_across_ = 0.0;
      have_ = true;
      return false;
    }
    const double a = std::min(1.0, dt_s / tau_s);
    mean_f_ += a * (f_m_s2 - mean_f_);
    mean_w_ += a * (w_rad_s - mean_w_);
    const Eigen::Vector3d dw = w_rad_s - mean_w_;
    const double f_norm = mean_f_.norm();
    const Eigen::Vector3d up = f_norm > 0.0 ? Eigen::Vector3d(mean_f_ / f_norm) : Eigen::Vector3d::Zero();
    var_f_ += a * ((f_m_s2 - mean_f_).squaredNorm() / 3.0 - var_f_);
    var_w_ += a * (dw.squaredNorm() / 3.0 - var_w_);
    var_w_across_ += a * ((dw - dw.dot(up) * up).squaredNorm() / 2.0 - var_w_across_);
    return true;
  }
  double accel_var_m2_s4() const { return var_f_; }  // per axis
  double rate_var_rad2_s2() const { return var_w_; }
  /// Per axis, over the two axes across the mean specific force (a yaw spin's rate change is along it).
  double rate_var_across_f_rad2_s2() const { return var_w_across_; }
  const Eigen::Vector3d& mean_rate_rad_s() const { return mean_w_; }

 private:
  Eigen::Vector3d mean_f_ = Eigen::Vector3d::Zero(), mean_w_ = Eigen::Vector3d::Zero();
  double var_f_ = 0.0, var_w_ = 0.0, var_w_across_ = 0.0;
  bool have_ = false;
};

}  // namespace sinu::est
