#pragma once
// Standing still, from the IMU: over the last ~second (exponential means,
// `tau_s`) the specific force and the rate scatter no more than a vehicle at
// rest with its engine running, and the mean rate is below a slow turn.
// A hovering multirotor is never still by this test: its rotors shake the IMU
// more than any threshold here. The navigator also asks the GNSS speed.
#include <algorithm>

#include "estimator/ins/imu_sample.hpp"

namespace sinu::est {

struct StillnessConfig {
  double tau_s = 1.0;
  double max_accel_std_m_s2 = 0.15;
  double max_rate_std_rad_s = 0.05;   // a consumer gyro's noise at 100 Hz is ~0.02
  double max_mean_rate_rad_s = 0.02;  // 1 deg/s: MEMS turn-on bias is below it
  double min_still_s = 1.0;           // that long before it counts
};

class Stillness {
 public:
  void configure(const StillnessConfig& cfg) {
    cfg_ = cfg;
    have_ = false;
    still_s_ = 0.0;
  }
  void add(const ImuSample& s, double dt_s) {
    const Eigen::Vector3d& f = s.specific_force_b_m_s2;
    const Eigen::Vector3d& w = s.angular_rate_b_rad_s;
    if (!have_) {
      mean_f_ = f;
      mean_w_ = w;
      var_f_ = var_w_ = 0.0;
      have_ = true;
      return;
    }
    const double a = std::min(1.0, dt_s / cfg_.tau_s);
    mean_f_ += a * (f - mean_f_);
    mean_w_ += a * (w - mean_w_);
    var_f_ += a * ((f - mean_f_).squaredNorm() / 3.0 - var_f_);
    var_w_ += a * ((w - mean_w_).squaredNorm() / 3.0 - var_w_);
    const bool quiet = var_f_ < cfg_.max_accel_std_m_s2 * cfg_.max_accel_std_m_s2 &&
                       var_w_ < cfg_.max_rate_std_rad_s * cfg_.max_rate_std_rad_s &&
                       mean_w_.cwiseAbs().maxCoeff() < cfg_.max_mean_rate_rad_s;
    still_s_ = quiet ? still_s_ + dt_s : 0.0;
  }
  bool still() const { return still_s_ >= cfg_.min_still_s; }

 private:
  StillnessConfig cfg_;
  Eigen::Vector3d mean_f_ = Eigen::Vector3d::Zero(), mean_w_ = Eigen::Vector3d::Zero();
  double var_f_ = 0.0, var_w_ = 0.0, still_s_ = 0.0;
  bool have_ = false;
};

}  // namespace sinu::est
