#include "firmware/host/replay/replay_result.hpp"

#include <cmath>
#include <numbers>

namespace sinu::replay {

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

double ReplayResult::rmse_pos_h_m() const { return rms(metrics.sum_h2, metrics.compared); }
double ReplayResult::rmse_pos_v_m() const { return rms(metrics.sum_v2, metrics.compared); }
double ReplayResult::rmse_vel_m_s() const { return rms(metrics.sum_vel2, metrics.compared_vel); }
double ReplayResult::rmse_att_deg() const { return rms(metrics.sum_att2, metrics.compared_att) * 180.0 / std::numbers::pi; }
double ReplayResult::gnss_rmse_pos_h_m() const { return rms(metrics.gnss_sum_h2, metrics.gnss_compared); }
double ReplayResult::gnss_rmse_pos_v_m() const { return rms(metrics.gnss_sum_v2, metrics.gnss_compared); }

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
