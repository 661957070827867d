#pragma once
// calib.json (written by `sinu calibrate`, issue 5) -> the EKF's sensor noise.
// Keys read: axes.<ax|ay|az|gx|gy|gz>.gm {tau_s, variance};
// axes.<..>.ar.<method>[p-1] {a: [1, a1..ap], variance}; axes.<..>.allan.N
// (white-noise density, optional); the AR models' sample rate from
// "sample_rate_hz" at the top level or inside "denoiser" (default 40 Hz).
#include <Eigen/Core>
#include <string>

#include "estimator/ekf/sensor_noise.hpp"
#include "estimator/prefilter/wavelet_prefilter.hpp"

namespace sinu::board {

struct CalibChoice {
  est::NoiseModelKind kind = est::NoiseModelKind::AutoRegressive;
  std::string ar_method = "burg";
  int ar_order = 3;
  // model: the AR fitted at the model rate calib.json chose (ar_model_rate), when it has one; imu: at the IMU rate.
  std::string ar_rate = "model";
};

/// The denoiser the models were fitted after (calib.json "denoiser"): the
/// same one must run in front of the INS for the models to describe its input.
struct DenoiserSpec {
  bool wavelet = false;        // false: none
  std::string name = "none";   // "db4", ...
  int levels = 0;
  /// calib.json's denoiser.keep_details_above_sigma x detail_sigma: details
  /// beyond the bench's noise pass (fast motion). Drop all without them.
  est::DetailThresholds keep_above = est::drop_every_detail();
  double keep_above_sigma = 0.0;  // 0: every detail dropped (the paper's approximation)
};

/// "none", "WAVELET:LEVELS" (e.g. "db4:3"): the approximation alone; false
/// with `error` otherwise.
bool parse_denoiser(const std::string& text, DenoiserSpec& out, std::string& error);

/// The unit's accelerometer errors known from a multi-position bench
/// calibration (calib.json "six_position": scale [ppm], misalignment [rad],
/// bias [m/s^2]), as the correction applied to every sample before the
/// filter: f = gain_inverse (f_raw - bias), gain = (I + diag s)(I + M).
struct AccelCorrection {
  bool present = false;
  Eigen::Matrix3d gain_inverse = Eigen::Matrix3d::Identity();
  Eigen::Vector3d bias_m_s2 = Eigen::Vector3d::Zero();
};

/// Reads calib.json's "six_position" when it has one (`out.present` false
/// when not); false with `error` = "calib.json: six_position.<key>: <why>".
bool load_accel_correction(const std::string& path, AccelCorrection& out, std::string& error);

/// Fills `noise` (and `denoiser` from calib.json's "denoiser" block, none if absent); false with `error` = "calib.json: <key>: <why>" otherwise.
bool load_calib(const std::string& path, const CalibChoice& choice, est::SensorNoise& noise, DenoiserSpec& denoiser,
                std::string& error);

}  // namespace sinu::board
