#include "firmware/host/replay/replay_result.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace sinu::replay {

void Excitation::add(const est::ImuSample& s) {
  if (s.specific_force_b_m_s2.allFinite() && std::isfinite(s.t_s)) {
    if (std::isnan(t_prev_s)) {
      t_first_s = s.t_s;
      f_held_m_s2 = s.specific_force_b_m_s2;
    } else {
      const double dt = std::max(0.0, s.t_s - t_prev_s);
      f_held_m_s2 += dt / (kHoldTau_s + dt) * (s.specific_force_b_m_s2 - f_held_m_s2);
    }
    t_prev_s = s.t_s;
    if (s.t_s - t_first_s >= 3.0 * kHoldTau_s) {  // past the start's transient
      f_min_m_s2 = f_min_m_s2.cwiseMin(f_held_m_s2);
      f_max_m_s2 = f_max_m_s2.cwiseMax(f_held_m_s2);
    }
  }
  w_min_rad_s = w_min_rad_s.cwiseMin(s.angular_rate_b_rad_s);
  w_max_rad_s = w_max_rad_s.cwiseMax(s.angular_rate_b_rad_s);
  if (s.has_temp) {
    ++temp_samples;
    temp_min_degC = std::min(temp_min_degC, s.temp_degC);
    temp_max_degC = std::max(temp_max_degC, s.temp_degC);
  }
  if (s.has_mag) ++mag_samples;
}

namespace {
double rms(double sum, std::uint64_t n) { return n ? std::sqrt(sum / static_cast<double>(n)) : NAN; }
}  // namespace

const char* health_status_name(HealthStatus s) {
  switch (s) {
    case HealthStatus::Ok: return "ok";
    case HealthStatus::Reset: return "reset";
    case HealthStatus::LostAndRecovered: return "lost_and_recovered";
    case HealthStatus::Lost: return "lost";
    case HealthStatus::NotAligned: return "not_aligned";
  }
  return "?";
}

HealthStatus ReplayResult::health() const {
  if (!aligned) return HealthStatus::NotAligned;
  if (last_flags & est::nav_flag::kLost) return HealthStatus::Lost;
  if (counters.lost_total_s > 0.0) return HealthStatus::LostAndRecovered;
  if (counters.resets() > 0) return HealthStatus::Reset;
  return HealthStatus::Ok;
}

std::string ReplayResult::not_aligned_reason() const {
  if (aligned) return "";
  if (scale.accel_refused) {
    return fmt::format("the accelerometer reads {:.3g} m/s^2 of specific force on average where gravity{} makes "
                       "{:.4g} m/s^2 ({:.3g}x): imu.csv's ax, ay, az must be m/s^2 (in g they read 0.1x)",
                       scale.mean_specific_force_m_s2,
                       scale.expected_over_gravity > 1.005 ? " and the GNSS's turns" : "",
                       scale.gravity_m_s2 * scale.expected_over_gravity, scale.specific_force_over_gravity);
  }
  if (scale.gyro_refused) {
    return fmt::format("the gyro scatters {:.3g} rad/s while the GNSS and the accelerometer (scatter {:.3g} m/s^2) say "
                       "the unit stands still; a MEMS gyro at rest scatters below 0.03: imu.csv's gx, gy, gz must be "
                       "rad/s (in deg/s they read 57x)",
                       scale.gyro_std_at_rest_rad_s, scale.accel_std_at_rest_m_s2);
  }
  // Fixes without a height are fused once aligned, but the INS starts from a 3-D fix.
  if (gnss.without_height > 0 && gnss.without_height >= gnss.used)
    return "the GNSS fixes have no height: RMC or GLL without a GGA sentence";
  if (gnss.used > 0 && std::isfinite(alignment.field_ratio)) {
    return fmt::format("no heading to start from: the GNSS never showed the unit moving, and the magnetometer's field "
                       "is not the Earth's as the World Magnetic Model has it here ({:.2f}x its strength, dip {:+.1f} "
                       "deg off: an uncalibrated hard or soft iron{}), so it gives none. --mag-declination DEG takes "
                       "the heading from the field as it is; a model file with the unit's hard iron (sinu diagnose "
                       "--apply on an earlier flight, --model-file) corrects it",
                       alignment.field_ratio, alignment.dip_difference_rad * 180.0 / std::numbers::pi,
                       alignment.saved_iron_refused ? "; the state file's iron does not explain it either: the iron "
                                                      "has moved since it was saved, a battery or payload swapped"
                                                    : "");
  }
  if (gnss.used > 0) return "no rest period and no GNSS motion to align on";
  if (source.fixes_after_imu > 0 && gnss.epochs == 0) {
    return fmt::format("gps.nmea's {} fixes all arrive after imu.csv's last sample (the first at t={:.7g} s, imu.csv "
                       "ends at {:.7g} s): both files must share one clock, in seconds",
                       source.fixes_after_imu, source.first_fix_after_imu_s, source.imu_end_s);
  }
  return "no GNSS position in the data: gps.nmea absent, empty or without a fix; the INS needs one to start from";
}

std::string ReplayResult::mag_refused_reason() const {
  if (!scale.mag_refused()) return "";
  return fmt::format("{} field samples read {:.3g}x the World Magnetic Model's {:.3g} uT here: imu.csv's mx, my, mz "
                     "must be uT (mG read 10x, G 0.01x, nT 1000x)",
                     scale.mag_refused_samples, scale.field_over_model, scale.model_field_uT);
}

double ReplayResult::rmse_pos_h_m() const { return rms(metrics.sum_h2, metrics.compared); }
double ReplayResult::rmse_pos_v_m() const { return rms(metrics.sum_v2, metrics.compared); }
double ReplayResult::rmse_vel_m_s() const { return rms(metrics.sum_vel2, metrics.compared_vel); }
double ReplayResult::rmse_att_deg() const { return rms(metrics.sum_att2, metrics.compared_att) * 180.0 / std::numbers::pi; }
// truth.csv holding the fixes themselves (the real drive): as they came.
double ReplayResult::gnss_retiming_s() const { return truth_is_gnss_input() ? 0.0 : gnss_latency_shift_s; }
double ReplayResult::gnss_rmse_pos_h_m() const { return rms(metrics.gnss_h.at(gnss_retiming_s()), metrics.gnss_compared); }
double ReplayResult::gnss_rmse_at_configured_pos_h_m() const { return rms(metrics.gnss_h.at(0.0), metrics.gnss_compared); }
double ReplayResult::gnss_rmse_pos_v_m() const { return rms(metrics.gnss_v.at(gnss_retiming_s()), metrics.gnss_compared); }

double ReplayResult::outage_drift_rms_m() const {
  double sum = 0.0;
  std::uint64_t n = 0;  // outages with a solution and truth inside them
  for (const OutageDrift& o : metrics.outages) {
    if (o.points == 0) continue;
    sum += o.max_drift_h_m * o.max_drift_h_m;
    ++n;
  }
  return rms(sum, n);
}

const EffectEstimate* ReplayResult::effect(est::Effect e) const {
  for (const EffectEstimate& x : effects) {
    if (x.effect == e) return &x;
  }
  return nullptr;
}

}  // namespace sinu::replay
