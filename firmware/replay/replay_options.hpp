#pragma once
// Everything `sinu replay` needs, parsed and validated by the CLI.
#include <cmath>
#include <string>
#include <vector>

#include "drivers/imu/icm20948.hpp"
#include "estimator/nav/navigator.hpp"
#include "firmware/replay/calib_json.hpp"
#include "firmware/replay/gnss_from_fix.hpp"

namespace sinu::replay {

struct Outage {
  double start_s = 0.0;     // dataset time t
  double duration_s = 0.0;
};

/// The effect states every model carries unless removed explicitly: the
/// unit's turn-on biases (a calibration's GM/AR models are zero-mean), the
/// receiver's slowly varying position error (GST's sigma split into it and
/// white noise) and its latency (NMEA arrives some tens of ms after the fix).
est::EffectSet default_effects();

struct ReplayOptions {
  std::string in_dir;       // dataset folder or raw recording file
  std::string truth_path;   // truth.csv; empty: the dataset folder's, if any
  drivers::Icm20948Config imu;  // driver settings for a raw recording (as `sinu convert`)
  std::string calib_path;   // empty: documented defaults (SensorNoise::defaults)
  std::string out_dir;
  CalibChoice calib;
  est::EffectSet effects = default_effects();
  double gps_period_s = 0.0;  // 0: every epoch
  std::vector<Outage> outages;
  // The fix's latency at arrival (initial value of the gps_latency state):
  // an NMEA epoch arrives some tens of ms after its time of validity.
  double gps_latency_s = 0.05;
  Eigen::Vector3d lever_arm_b_m = Eigen::Vector3d::Zero();
  double nav_rate_hz = 10.0;  // nav.csv rows per second; 0: every IMU sample
  double gate_sigma = 5.0;
  GnssSigmaConfig sigma;
  std::string denoise = "auto";  // auto: calib.json's denoiser (none without calib); none; WAVELET:LEVELS
  bool quiet = false;
  double process_noise_scale = 1.0;  // times the sensor model's coloured-error variances
  double mag_sigma_uT = 1.0;  // magnetometer noise + disturbance, 1 sigma per axis
  // Learn the GNSS velocity and magnetometer noise from the innovations,
  // starting from the sigmas above; a sigma given on the command line is kept fixed.
  bool adapt_velocity_noise = true;
  bool adapt_mag_noise = true;
  bool use_mag = true;
  est::VehicleKind vehicle = est::VehicleKind::Air;  // ground: non-holonomic constraint
  // IMU full scales for the clipping screen; 0: unknown (a recording's driver
  // settings fill them; for a dataset the user gives --accel-range/--gyro-range).
  double accel_range_m_s2 = 0.0;
  double gyro_range_rad_s = 0.0;
  double mag_declination_deg = NAN;  // set: align with the magnetometer at rest
};

/// Parses "START:DURATION,START:DURATION"; false with `error` on bad input.
bool parse_outages(const std::string& text, std::vector<Outage>& out, std::string& error);
/// Parses "accel_scale,lever_arm"; false with `error` naming the bad effect.
bool parse_effects(const std::string& text, est::EffectSet& out, std::string& error);
/// The defaults, plus `added`, minus `removed` (both comma lists; "none" removes all defaults).
bool resolve_effects(const std::string& added, const std::string& removed, est::EffectSet& out, std::string& error);

}  // namespace sinu::replay
