#pragma once
// Covariance prediction at a lower rate than the strapdown (PX4 EKF2 and most
// INS/GNSS filters do the same): the IMU intervals since the last prediction
// are summed into one PredictInput with time-weighted mean inputs, and the
// filter predicts once over the sum. The INS itself still integrates every
// sample. Flushed when the interval reaches its period and before every
// measurement, so P is always predicted to the time of the update.
// Over 0.1 s the first-order transition I + F dt is as good as 4 steps of
// 0.025 s to O(|F dt|^2) = O(1e-2) of the already small coupling terms.
#include <cmath>

#include "estimator/ekf/error_state_filter.hpp"

namespace sinu::est {

class PredictAccumulator {
 public:
  void add(const PredictInput& in) {
    const double w = in.dt_s;
    f_b_ += w * in.specific_force_b_m_s2;
    w_b_ += w * in.angular_rate_b_rad_s;
    f_n_ += w * in.specific_force_n_m_s2;
    temp_ += w * in.temp_delta_degC;
    accel_floor2_ += w * in.accel_white_floor_m_s2_rthz * in.accel_white_floor_m_s2_rthz;
    gyro_floor2_ += w * in.gyro_white_floor_rad_s_rthz * in.gyro_white_floor_rad_s_rthz;
    dt_ += w;
    nav_ = in.nav;
  }
  double pending_s() const { return dt_; }
  /// Predicts over everything added since the last flush (nothing if empty).
  void flush(ErrorStateFilter& filter) {
    if (!(dt_ > 0.0)) return;
    PredictInput in;
    in.nav = nav_;
    in.specific_force_b_m_s2 = f_b_ / dt_;
    in.angular_rate_b_rad_s = w_b_ / dt_;
    in.specific_force_n_m_s2 = f_n_ / dt_;
    in.temp_delta_degC = temp_ / dt_;
    in.accel_white_floor_m_s2_rthz = std::sqrt(accel_floor2_ / dt_);
    in.gyro_white_floor_rad_s_rthz = std::sqrt(gyro_floor2_ / dt_);
    in.dt_s = dt_;
    filter.predict(in);
    clear();
  }
  void clear() {
    f_b_.setZero();
    w_b_.setZero();
    f_n_.setZero();
    temp_ = dt_ = accel_floor2_ = gyro_floor2_ = 0.0;
  }

 private:
  Eigen::Vector3d f_b_ = Eigen::Vector3d::Zero(), w_b_ = Eigen::Vector3d::Zero(), f_n_ = Eigen::Vector3d::Zero();
  double temp_ = 0.0, dt_ = 0.0, accel_floor2_ = 0.0, gyro_floor2_ = 0.0;
  const NavState* nav_ = nullptr;
};

}  // namespace sinu::est
