#pragma once
// Stochastic model of the six inertial sensor errors, as calibrated by
// `sinu calibrate` (calib.json): first-order Gauss-Markov per axis, or an
// AR(p) process per axis in MATLAB's convention
//   x_k + a1 x_{k-1} + ... + ap x_{k-p} = w_k,  var(w) = variance,
// defined at the calibration's sample period. Plus the white noise that
// drives the navigation errors (Allan N). Defaults are documented in
// defaults() and README ("sinu replay").
#include <array>

#include "estimator/ekf/state_layout.hpp"

namespace sinu::est {

enum class NoiseModelKind { GaussMarkov, AutoRegressive };

struct GaussMarkovAxis {
  double tau_s = 300.0;
  double variance = 0.0;  // stationary variance [unit^2]
};

struct ArAxis {
  Eigen::Index order = 1;
  std::array<double, kMaxArOrder + 1> a{1.0};  // a[0] = 1
  double variance = 0.0;                       // driving-noise variance [unit^2]
};

struct SensorNoise {
  NoiseModelKind kind = NoiseModelKind::GaussMarkov;
  std::array<GaussMarkovAxis, kSensorAxes> gm{};
  std::array<ArAxis, kSensorAxes> ar{};
  double ar_sample_period_s = 0.025;     // the AR models' time step
  double accel_white_m_s2_rthz = 0.0;    // velocity random walk density
  double gyro_white_rad_s_rthz = 0.0;    // angle random walk density
  // Random-walk density of the accel_bias / gyro_bias states [unit/sqrt(s)],
  // from the Allan deviation at cluster times of minutes (calib_json.cpp,
  // bias_walk_from_allan). The GM/AR models
  // fitted to the denoised static series follow the error over seconds; this
  // covers the slow wander they cannot (minutes). 0: EffectTuning's default.
  double accel_bias_walk = 0.0;
  double gyro_bias_walk = 0.0;

  /// States per axis in the EKF.
  Eigen::Index order() const;

  /// Defaults for a consumer MEMS IMU of the ICM-20948 class (datasheet
  /// noise densities, in-run bias ~0.05 m/s^2 and ~0.3 deg/s over 300 s):
  /// accel GM sigma 0.05 m/s^2 tau 300 s, N 2.3e-3 m/s^2/rtHz;
  /// gyro GM sigma 5e-3 rad/s tau 300 s, N 2.6e-4 rad/s/rtHz.
  /// The AR default is the exact AR(1) equivalent of that GM at 40 Hz.
  static SensorNoise defaults(NoiseModelKind kind);

  /// Scales every coloured-error variance (GM variances, AR driving
  /// variances, bias-state walks squared) by `factor`; white noise unchanged.
  void scale_coloured(double factor);
};

}  // namespace sinu::est
