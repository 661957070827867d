#include "firmware/board/nav_unit.hpp"

#include <algorithm>
#include <numbers>

#include "drivers/imu/icm20948_registers.hpp"
#include "estimator/prefilter/wavelet_prefilter.hpp"

namespace sinu::board {

est::ImuSample to_estimator(const drivers::ImuSample& d) {
  est::ImuSample s;
  s.t_s = hal::ns_to_s(d.t_ns);  // as imu.csv's t reads back: ns_to_s rounds correctly
  s.specific_force_b_m_s2 = {d.specific_force_b_m_s2[0], d.specific_force_b_m_s2[1], d.specific_force_b_m_s2[2]};
  s.angular_rate_b_rad_s = {d.angular_rate_b_rad_s[0], d.angular_rate_b_rad_s[1], d.angular_rate_b_rad_s[2]};
  s.has_mag = d.has_mag;
  if (s.has_mag) s.mag_b_uT = {d.mag_b_uT[0], d.mag_b_uT[1], d.mag_b_uT[2]};
  s.has_temp = true;  // the driver reads the temperature with every sample
  s.temp_degC = d.temp_degC;
  return s;
}

void full_scales(const drivers::Icm20948Config& imu, double& accel_m_s2, double& gyro_rad_s) {
  accel_m_s2 = 32767.0 * drivers::icm20948::accel_m_s2_per_lsb(static_cast<int>(imu.accel_range));
  gyro_rad_s = 32767.0 * drivers::icm20948::gyro_rad_s_per_lsb(static_cast<int>(imu.gyro_range));
}

bool NavUnit::init(const NavUnitConfig& c, est::NavObserver* observer, std::string& error) {
  cfg_ = c;
  est::NavigatorConfig cfg;
  cfg.noise = est::SensorNoise::defaults(c.calib.kind);
  denoiser_ = {};
  if (!c.calib_path.empty() && !load_calib(c.calib_path, c.calib, cfg.noise, denoiser_, error)) return false;
  cfg.noise.scale_coloured(c.process_noise_scale);
  if (c.denoise != "auto" && !parse_denoiser(c.denoise, denoiser_, error)) return false;
  prefilter_.reset();
  if (denoiser_.wavelet) {
    prefilter_ = est::make_wavelet_prefilter(*est::wavelet::parse_wavelet(denoiser_.name), denoiser_.levels);
  }
  cfg.effects = c.effects;
  cfg.use_mag = c.use_mag;
  cfg.vehicle = c.vehicle;
  cfg.mag_sigma_uT = c.mag_sigma_uT;
  cfg.gnss_velocity_noise.enabled = c.adapt_velocity_noise;
  cfg.mag_noise.enabled = c.adapt_mag_noise;
  cfg.alignment.use_mag = c.use_mag;
  if (std::isfinite(c.mag_declination_deg)) {
    cfg.alignment.declination_known = true;
    cfg.alignment.mag_declination_rad = c.mag_declination_deg * std::numbers::pi / 180.0;
  }
  cfg.screen.accel_range_m_s2 = c.accel_range_m_s2;
  cfg.screen.gyro_range_rad_s = c.gyro_range_rad_s;
  cfg.gate_sigma = c.gate_sigma;
  cfg.gps_latency_s = c.gps_latency_s;
  cfg.lever_arm_b_m = c.lever_arm_b_m;
  cfg.horizon_s = std::max(0.3, c.gps_latency_s + 0.25);
  nav_ = std::make_unique<est::Navigator>();
  nav_->init(cfg, observer, prefilter_.get());
  return true;
}

bool NavUnit::observation(const drivers::GpsFix& fix, est::GnssObservation& z) const {
  return gnss_from_fix(fix, cfg_.sigma, z);
}

bool NavUnit::push_fix(const drivers::GpsFix& fix) {
  est::GnssObservation z;
  if (!observation(fix, z)) return false;
  nav_->push_gnss(z);
  return true;
}

}  // namespace sinu::board
