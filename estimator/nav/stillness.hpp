#pragma once
// Standing still, from the IMU: over the last ~second (exponential means,
// `tau_s`) the specific force and the rate scatter no more than a vehicle at
// rest with its engine running, and the mean rate is below a slow turn.
// A hovering multirotor is never still by this test: its rotors shake the IMU
// more than any threshold here. The navigator also asks the GNSS speed.
#include "estimator/ins/imu_sample.hpp"
#include "estimator/nav/imu_scatter.hpp"

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
    scatter_.reset();
    still_s_ = 0.0;
  }
  void add(const ImuSample& s, double dt_s) {
    if (!scatter_.add(s.specific_force_b_m_s2, s.angular_rate_b_rad_s, dt_s, cfg_.tau_s)) return;
    const bool quiet = scatter_.accel_var_m2_s4() < cfg_.max_accel_std_m_s2 * cfg_.max_accel_std_m_s2 &&
                       scatter_.rate_var_rad2_s2() < cfg_.max_rate_std_rad_s * cfg_.max_rate_std_rad_s &&
                       scatter_.mean_rate_rad_s().cwiseAbs().maxCoeff() < cfg_.max_mean_rate_rad_s;
    still_s_ = quiet ? still_s_ + dt_s : 0.0;
  }
  bool still() const { return still_s_ >= cfg_.min_still_s; }

 private:
  StillnessConfig cfg_;
  ImuScatter scatter_;
  double still_s_ = 0.0;
};

}  // namespace sinu::est
