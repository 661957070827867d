#pragma once
// What a navigation unit is made of, in the user's words: the calibration and
// sensor-error model, the denoiser, the effect states, the GNSS and
// magnetometer settings and what carries the unit. `sinu fly` fills it from
// sinu.toml and its options, `sinu replay` and `sinu diagnose` from theirs;
// NavUnit::init turns it into a running navigator.
#include <Eigen/Core>
#include <array>
#include <bitset>
#include <cmath>
#include <string>

#include "estimator/nav/navigator.hpp"
#include "firmware/board/calibration_reader.hpp"
#include "firmware/board/effect_selection.hpp"
#include "firmware/board/gnss_from_fix.hpp"

namespace sinu::board {

struct NavUnitConfig {
  std::string calib_path;       // calib.json; empty: documented defaults (SensorNoise::defaults)
  CalibChoice calib;            // model: GM or AR (method, order)
  std::string denoise = "auto"; // auto: calib.json's denoiser (none without calib); none; WAVELET:LEVELS
  est::EffectSet effects = default_effects();
  std::string model_path;       // a model file (model_file.hpp): effects known from an earlier flight, added to `effects`
  // Model-file effects learnt again from the vocabulary's prior instead of
  // the file's value (diagnose asks: has it changed since? an antenna moved).
  est::EffectSet relearn;
  // Components of an effect held at its assumed value (zero) instead of
  // learnt, unless a model file gives the effect: what the flight cannot
  // determine (diagnose: a scale, misalignment or g-sensitivity term whose
  // input axis never moved).
  std::array<std::bitset<est::kMaxEffectDim>, est::kEffectCount> held{};
  // The fix's latency at arrival (initial value of the gps_latency state):
  // an NMEA epoch arrives some tens of ms after its time of validity.
  double gps_latency_s = 0.05;
  // The IMU's samples stamped this much late (NavigatorConfig::imu_latency_s).
  double imu_latency_s = 0.0;
  Eigen::Vector3d lever_arm_b_m = Eigen::Vector3d::Zero();  // antenna minus IMU, body FRD
  double gate_sigma = 5.0;
  GnssSigmaConfig sigma;
  double process_noise_scale = 1.0;  // times the sensor model's coloured-error variances
  // Times the bias states' random-walk densities (diagnose asks: did a bias move more than calibrated?).
  double accel_bias_walk_scale = 1.0, gyro_bias_walk_scale = 1.0;
  double mag_sigma_uT = 1.0;         // magnetometer noise + disturbance, 1 sigma per axis
  // Learn the GNSS velocity and magnetometer noise from the innovations,
  // starting from the sigmas above (a sigma the user gives is kept fixed).
  bool adapt_velocity_noise = true;
  bool adapt_mag_noise = true;
  bool adapt_position_scale = true;  // a factor on GNSS position sigmas no GST states
  bool use_mag = true;
  est::VehicleKind vehicle = est::VehicleKind::Auto;  // ground: non-holonomic constraint; auto: detected
  // IMU full scales for the clipping screen; 0: unknown (on the board and for
  // a recording the driver's settings give them).
  double accel_range_m_s2 = 0.0;
  double gyro_range_rad_s = 0.0;
  double mag_declination_deg = NAN;  // set: align with the magnetometer at rest
  // The state file (state_file.hpp): read at start, used by a restart whose
  // first dated fix is at most state_max_age_s after it was saved (a reboot
  // in the air; an older one is from another flight, what it knew of the
  // receiver's error long gone), written every state_period_s once aligned.
  // "": none.
  std::string state_path;
  double state_max_age_s = 600.0;
  double state_period_s = 5.0;
};

}  // namespace sinu::board
