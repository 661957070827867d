#pragma once
// Error-state EKF around the strapdown INS: covariance prediction, sensor
// compensation with the current estimates, and feedback of a correction.
// Measurements are built by the aiding sources (ekf/aiding/*) and fused with
// fuse_measurement(); the filter only owns the state and its bookkeeping.
#include "estimator/ekf/effect_tuning.hpp"
#include "estimator/ekf/sensor_error_model.hpp"
#include "estimator/ekf/sensor_noise.hpp"
#include "estimator/ekf/state_layout.hpp"
#include "estimator/ins/imu_sample.hpp"
#include "estimator/ins/nav_state.hpp"
#include "estimator/ins/strapdown.hpp"

namespace sinu::est {

/// Initial navigation uncertainty (1 sigma).
struct NavUncertainty {
  Eigen::Vector3d pos_ned_m{3.0, 3.0, 5.0};
  Eigen::Vector3d vel_ned_m_s{0.5, 0.5, 0.5};
  Eigen::Vector3d att_rad{0.02, 0.02, 0.1};
};

/// What the INS saw over the last interval, for the error dynamics.
struct PredictInput {
  const NavState* nav = nullptr;              // after the strapdown step
  Eigen::Vector3d specific_force_b_m_s2;      // compensated, mid-interval
  Eigen::Vector3d angular_rate_b_rad_s;       // compensated, mid-interval
  Eigen::Vector3d specific_force_n_m_s2;      // mean over the interval
  double temp_delta_degC = 0.0;               // temperature minus reference
  double dt_s = 0.0;
};

class ErrorStateFilter {
 public:
  void init(const StateLayout& layout, const SensorNoise& noise, const EffectTuning& tuning,
            const NavUncertainty& nav0);

  /// Propagates P and the sensor-state mean over one interval.
  void predict(const PredictInput& in);

  /// Applies the correction dx (from fuse_measurement) to nav and to the
  /// sensor/effect estimates, then zeroes it.
  void feedback(StateVec& dx, NavState& nav);

  /// Raw sample -> compensated body rates (sensor-error states, scale,
  /// temperature coefficients).
  BodyRates compensate(const ImuSample& raw) const;

  const StateLayout& layout() const { return layout_; }
  StateMat& P() { return P_; }
  const StateMat& P() const { return P_; }
  /// Current estimated error of a sensor axis [m/s^2 | rad/s].
  double sensor_error(Eigen::Index axis) const;
  double sensor_error_sigma(Eigen::Index axis) const;
  /// Nominal value of effect component i (scale [-], lever arm [m], ...).
  double effect(Effect e, Eigen::Index i) const;
  double effect_sigma(Effect e, Eigen::Index i) const;
  Eigen::Vector3d lever_arm_b_m() const { return lever_arm_b_; }
  double gps_latency_s() const { return latency_s_; }
  Eigen::Vector3d gps_position_bias_ned_m() const { return gps_bias_ned_; }
  Eigen::Vector3d mag_earth_field_n_uT() const { return mag_field_n_; }
  Eigen::Vector3d mag_hard_iron_b_uT() const { return mag_hard_iron_b_; }
  /// Soft-iron matrix I + D (identity without the mag_soft_iron states).
  Eigen::Matrix3d mag_soft_iron() const;
  const EffectTuning& tuning() const { return tuning_; }

  /// Starts the magnetometer model from one sample: F_n = C_nb (m_b - h_b),
  /// with the uncertainty (and the attitude correlation) that the current
  /// attitude error and the sample's noise give it.
  void start_mag_field(const NavState& nav, const Eigen::Vector3d& mag_b_uT, double noise_sigma_uT);

  /// Seeds the gyro bias measured at rest and its uncertainty [rad/s]: into
  /// the gyro_bias states when active, else into the sensor-error states
  /// (all lags of an AR block get the same value).
  void seed_gyro_bias(const Eigen::Vector3d& bias_rad_s, double sigma_rad_s);
  void set_lever_arm(const Eigen::Vector3d& l) { lever_arm_b_ = l; }
  void set_gps_latency(double s) { latency_s_ = s; }
  void set_reference_temperature(double t) { temp_ref_degC_ = t; }
  double reference_temperature() const { return temp_ref_degC_; }

 private:
  Eigen::Index hat_index(Eigen::Index axis) const { return axis * layout_.order; }
  void build_transition(const PredictInput& in, int ar_steps, StateMat& Phi, StateVec& q) const;

  StateLayout layout_;
  SensorNoise noise_;
  EffectTuning tuning_;
  StateMat P_;
  StateVec sensor_hat_;  // mean of the sensor-error states (size sensor.size)
  std::array<AxisBlock, kSensorAxes> ar_step_{};  // companion matrices
  double ar_clock_s_ = 0.0;
  Eigen::Vector3d accel_scale_ = Eigen::Vector3d::Zero(), gyro_scale_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_temp_ = Eigen::Vector3d::Zero(), gyro_temp_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_ = Eigen::Vector3d::Zero(), gyro_bias_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d lever_arm_b_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d gps_bias_ned_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d mag_field_n_ = Eigen::Vector3d::Zero(), mag_hard_iron_b_ = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 6, 1> mag_soft_iron_ = Eigen::Matrix<double, 6, 1>::Zero();  // D xx yy zz xy xz yz
  double latency_s_ = 0.0;
  double temp_ref_degC_ = 0.0;
};

}  // namespace sinu::est
