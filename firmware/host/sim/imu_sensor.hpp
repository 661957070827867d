#pragma once
// The simulated 9-axis IMU: true motion -> what the sensor writes.
//   accel = Q( (I+diag s_a)(I+M_a) f_b + b_a(t) + k_a (T - 25) )
//   gyro  = Q( (I+diag s_g)(I+M_g) w_ib_b + G f_b + b_g(t) + k_g (T - 25) )
//   mag   = Q( S C_bn m_n + h + noise )
// b(t) is the stochastic error of imu_error_model.hpp, Q the 16-bit
// quantiser; s, M, k, G, S, h are the effects (identity/zero when absent).
#include <Eigen/Core>
#include <array>

#include "firmware/host/sim/effects.hpp"
#include "firmware/host/sim/error_processes.hpp"
#include "firmware/host/sim/imu_error_model.hpp"

namespace sinu::sim {

struct ImuOutput {
  Eigen::Vector3d specific_force_b_m_s2, angular_rate_b_rad_s, mag_b_uT;
  double temp_degC = 0.0;
};

class TriadErrors {
 public:
  void init(const TriadErrorModel& m, double dt_s, Rng& rng);
  /// Advances every process one sample and returns the total error.
  Eigen::Vector3d step(Rng& rng);
  /// Adds error, quantises and clips.
  Eigen::Vector3d measure(const Eigen::Vector3d& value) const;

 private:
  TriadErrorModel model_;
  std::array<double, 3> white_sigma_{};
  std::array<GaussMarkov, 3> gm_{};
  std::array<PeriodicRandom, 3> periodic_{};
  std::array<RandomWalk, 3> rrw_{};
};

class ImuSensor {
 public:
  ImuSensor(const ImuErrorModel& model, const Effects& effects, const Eigen::Vector3d& earth_field_n_uT,
            double dt_s, Rng& noise_rng);
  void set_earth_field(const Eigen::Vector3d& earth_field_n_uT) { earth_field_n_uT_ = earth_field_n_uT; }
  ImuOutput sample(const Eigen::Vector3d& specific_force_b, const Eigen::Vector3d& omega_ib_b,
                   const Eigen::Matrix3d& C_nb, double temp_degC);

 private:
  ImuErrorModel model_;
  Rng& rng_;
  TriadErrors accel_, gyro_;
  Eigen::Matrix3d accel_gain_, gyro_gain_, g_sensitivity_, mag_axes_;  // mag_axes_: soft iron x misalignment
  Eigen::Vector3d accel_temp_k_, gyro_temp_k_, hard_iron_, motor_field_, earth_field_n_uT_;
  double mag_latency_s_ = 0.0;
};

}  // namespace sinu::sim
