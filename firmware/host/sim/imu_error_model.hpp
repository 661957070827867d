#pragma once
// Parameters of the IMU's stochastic error model, per axis, in SI units.
// Sampled at dt, the error of one axis is
//   e_k = turn_on_bias + white_k + gm_k + periodic_k + rrw_k
// with white_k ~ N(0, (white_noise_density)^2 / dt), gm a first-order
// Gauss-Markov process (gm_sigma, gm_tau_s), periodic a damped resonator
// (periodic_sigma, periodic_period_s, periodic_damping) and rrw a random
// walk (rate_random_walk). The sum is added to the true value and the result
// quantised to `quantisation_step` and clipped to +-full_scale (16-bit ADC).
// docs/simulation.md describes the defaults and why they are what they are.
#include <array>

#include "firmware/host/sim/rng.hpp"

namespace sinu::sim {

struct AxisErrorModel {
  double white_noise_density = 0.0;  // [unit/sqrt(Hz)] (unit = m/s^2 or rad/s)
  double gm_sigma = 0.0;             // [unit] stationary std of the GM bias
  double gm_tau_s = 1.0;             // [s] GM correlation time
  double periodic_sigma = 0.0;       // [unit] stationary std of the resonator output
  double periodic_period_s = 10.0;   // [s] damped period 2 pi / w_d
  double periodic_damping = 0.05;    // damping ratio zeta (lightly damped: << 1)
  double rate_random_walk = 0.0;     // [unit/sqrt(s)] random-walk coefficient
  double turn_on_bias = 0.0;         // [unit] constant for the session
};

struct TriadErrorModel {
  std::array<AxisErrorModel, 3> axis{};
  double full_scale = 0.0;         // [unit] +- range of the 16-bit output
  double quantisation_step = 0.0;  // [unit] = 2 full_scale / 65536; 0 = no quantisation
};

struct MagErrorModel {
  double white_noise_sigma_uT = 0.0;  // per sample
  double quantisation_step_uT = 0.0;  // AK09916: 0.15 uT/LSB
};

struct TempSensorModel {
  double white_noise_sigma_degC = 0.0;
  double quantisation_step_degC = 0.0;  // ICM-20948: 1 / 333.87 degC/LSB
};

struct ImuErrorModel {
  TriadErrorModel accel, gyro;  // m/s^2, rad/s
  MagErrorModel mag;
  TempSensorModel temp;
};

/// The default model: an ICM-20948-class MEMS IMU at +-4 g / +-500 dps,
/// per-axis values drawn around the nominal ones from `rng` (so each seed is
/// a different unit), turn-on biases drawn from their spread.
ImuErrorModel draw_default_imu_error_model(Rng& rng);
/// No stochastic error and no quantisation: the true motion, exactly.
ImuErrorModel ideal_imu_error_model();

}  // namespace sinu::sim
