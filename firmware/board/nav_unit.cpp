#include "firmware/board/nav_unit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>

#include "drivers/imu/icm20948_registers.hpp"
#include "estimator/prefilter/correcting_prefilter.hpp"
#include "estimator/prefilter/wavelet_prefilter.hpp"
#include "firmware/board/model_file.hpp"

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
  AccelCorrection accel;
  if (!c.calib_path.empty() && !load_accel_correction(c.calib_path, accel, error)) return false;
  cfg.noise.scale_coloured(c.process_noise_scale);
  cfg.noise.accel_bias_walk *= c.accel_bias_walk_scale;
  cfg.noise.gyro_bias_walk *= c.gyro_bias_walk_scale;
  if (c.denoise != "auto" && !parse_denoiser(c.denoise, denoiser_, error)) return false;
  prefilter_.reset();
  if (denoiser_.wavelet) {
    prefilter_ = est::make_wavelet_prefilter(*est::wavelet::parse_wavelet(denoiser_.name), denoiser_.levels,
                                             denoiser_.keep_above);
  }
  // The unit's scale, misalignment and bias from a multi-position calibration:
  // known values, corrected before the denoiser and the filter (no states).
  correction_.reset();
  if (accel.present) {
    correction_ = std::make_unique<est::CorrectingPrefilter>(prefilter_.get(), accel.gain_inverse, accel.bias_m_s2);
  }
  cfg.effects = c.effects;
  double file_imu_latency_s = 0.0;
  if (!c.model_path.empty() &&
      !read_model_file(c.model_path, cfg.effects, cfg.tuning.prior, file_imu_latency_s, error))
    return false;
  for (std::size_t e = 0; e < est::kEffectCount; ++e) {
    est::EffectPrior& p = cfg.tuning.prior[e];
    if (c.relearn.has(static_cast<est::Effect>(e))) p.given = false;
    if (c.held[e].none() || p.given) continue;
    p.given = true;
    for (std::size_t k = 0; k < p.value.size(); ++k) {
      p.value[k] = 0.0;
      p.sigma[k] = c.held[e][k] ? 0.0 : cfg.tuning.initial_sigma[e];
    }
  }
  cfg.use_mag = c.use_mag;
  cfg.vehicle = c.vehicle;
  cfg.mag_sigma_uT = c.mag_sigma_uT;
  cfg.gnss_velocity_noise.enabled = c.adapt_velocity_noise;
  cfg.mag_noise.enabled = c.adapt_mag_noise;
  cfg.gnss_position_scale.enabled = c.adapt_position_scale;
  cfg.alignment.use_mag = c.use_mag;
  if (std::isfinite(c.mag_declination_deg)) {
    cfg.alignment.declination_known = true;
    cfg.alignment.mag_declination_rad = c.mag_declination_deg * std::numbers::pi / 180.0;
  }
  cfg.screen.accel_range_m_s2 = c.accel_range_m_s2;
  cfg.screen.gyro_range_rad_s = c.gyro_range_rad_s;
  cfg.gate_sigma = c.gate_sigma;
  cfg.gps_latency_s = c.gps_latency_s;
  cfg.imu_latency_s = imu_latency_in_use(c.imu_latency_s, file_imu_latency_s);
  cfg.lever_arm_b_m = c.lever_arm_b_m;
  cfg.horizon_s = std::max(0.3, c.gps_latency_s + 0.25);
  nav_ = std::make_unique<est::Navigator>();
  nav_->init(cfg, observer, correction_ ? correction_.get() : prefilter_.get());
  warm_pending_ = state_write_failed_ = false;
  last_state_save_t_s_ = -1e300;
  state_note_.clear();
  if (!c.state_path.empty()) {
    std::string state_error;
    if (!std::ifstream(c.state_path)) {
      state_note_ = c.state_path + ": no state file yet: a cold start";
    } else if (!read_state_file(c.state_path, saved_, state_error)) {
      state_note_ = state_error + ": a cold start";  // a bad file must not keep the unit from flying
    } else {
      warm_pending_ = true;
    }
    if (!state_note_.empty()) ++state_note_version_;
  }
  return true;
}

void NavUnit::decide_warm_start(std::int64_t fix_utc_ms) {
  warm_pending_ = false;
  const double age_s = static_cast<double>(fix_utc_ms - saved_.saved_utc_ms) * 1e-3;
  char buf[160];
  if (!(age_s >= 0.0 && age_s <= cfg_.state_max_age_s)) {
    std::snprintf(buf, sizeof buf, ": saved %.0f s before the first fix (more than %.0f s, or after it): a cold start",
                  age_s, cfg_.state_max_age_s);
  } else if (!nav_->warm_start(saved_.warm, age_s)) {
    std::snprintf(buf, sizeof buf, ": the navigator was aligned before the first dated fix: a cold start");
  } else {
    std::snprintf(buf, sizeof buf, ": a warm start from the state saved %.1f s before the first fix", age_s);
  }
  state_note_ = cfg_.state_path + buf;
  ++state_note_version_;
}

void NavUnit::save_state(bool final) {
  if (state_write_failed_ || !nav_->aligned() || !have_fix_ || !fix_has_utc_) return;
  const double t = nav_->nav().t_s;
  if (!final && t - last_state_save_t_s_ < cfg_.state_period_s) return;
  last_state_save_t_s_ = t;
  SavedState s{nav_->warm_state(), utc_ms_at(t)};
  std::string error;
  if (!write_state_file(cfg_.state_path, s, error)) {
    state_write_failed_ = true;  // said once; the unit flies on
    state_note_ += (state_note_.empty() ? "" : "; ") + error + " (the state is not saved)";
    ++state_note_version_;
  }
}

bool NavUnit::observation(const drivers::GpsFix& fix, est::GnssObservation& z) const {
  return gnss_from_fix(fix, cfg_.sigma, z);
}

bool NavUnit::push_fix(const drivers::GpsFix& fix) {
  est::GnssObservation z;
  if (!observation(fix, z)) return false;
  push_fix(fix, z);
  return true;
}

void NavUnit::push_fix(const drivers::GpsFix& fix, const est::GnssObservation& z) {
  const bool dated = fix.date.has_value();
  const std::int64_t utc_ms = dated ? utc_epoch_ms(*fix.date, fix.utc_ms) : 0;
  if (warm_pending_ && dated) decide_warm_start(utc_ms);  // before the fix can align the unit
  nav_->push_gnss(z);
  have_fix_ = true;
  fix_arrival_s_ = fix.arrival_s;
  fix_has_utc_ = dated;
  if (fix_has_utc_) fix_utc_ms_ = utc_ms;
  // GGA's: an epoch without one (RMC alone, fused north and east) keeps the last.
  if (fix.has_gga) {
    geoid_sep_m_ = fix.geoid_sep_m.value_or(0.0);
    satellites_ = fix.sats.value_or(0);
    hdop_ = fix.hdop.value_or(99.99);
  }
}

std::int64_t utc_epoch_ms(const drivers::UtcDate& d, drivers::UtcMs time_of_day_ms) {
  // Days from 1970-01-01 of a proleptic Gregorian date (the era algorithm:
  // 400-year eras of 146097 days, years starting in March).
  const int y = d.year - (d.month <= 2 ? 1 : 0);
  const int era = (y >= 0 ? y : y - 399) / 400;
  const int yoe = y - era * 400;
  const int mp = (d.month + 9) % 12;
  const int doy = (153 * mp + 2) / 5 + d.day - 1;
  const int doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  const std::int64_t days = std::int64_t{era} * 146097 + doe - 719468;
  return days * 86'400'000 + time_of_day_ms;
}

void NavUnit::solution(const est::NavOutput& o, NavSolution& sol) const {
  constexpr double kRadToDeg = 180.0 / std::numbers::pi;
  sol.t_s = o.nav.t_s;
  sol.aligned = (o.flags & est::nav_flag::kAligned) != 0;
  sol.lat_deg = o.nav.lat_rad * kRadToDeg;
  sol.lon_deg = o.nav.lon_rad * kRadToDeg;
  sol.h_ellipsoid_m = o.nav.h_m;
  sol.v_ned_m_s = o.nav.v_n_m_s;
  sol.q_nb = o.nav.q_nb;
  sol.angular_rate_b_rad_s = o.angular_rate_b_rad_s;
  sol.P_nav = o.P_nav;
  sol.flags = o.flags;
  sol.geoid_sep_m = geoid_sep_m_;
  sol.satellites = satellites_;
  sol.hdop = hdop_;
  sol.has_utc = have_fix_ && fix_has_utc_;
  if (sol.has_utc) {
    sol.utc_ms = utc_ms_at(o.nav.t_s);
  }
}

std::int64_t NavUnit::utc_ms_at(double t_s) const {
  // The fix was valid at its arrival less the latency (estimated, or as configured).
  const double latency = nav_->filter().gps_latency_s();
  return fix_utc_ms_ + std::llround((t_s - (fix_arrival_s_ - latency)) * 1000.0);
}

}  // namespace sinu::board
