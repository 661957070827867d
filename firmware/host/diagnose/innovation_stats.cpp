#include "firmware/host/diagnose/innovation_stats.hpp"

#include <cmath>
#include <numbers>

#include "estimator/ins/rotation.hpp"

namespace sinu::diagnose {

namespace {
constexpr double kPhasePeriodS = 0.1;  // as nav.csv's rows
}  // namespace

void ComponentStats::add(double y, double s, bool accepted) {
  ++count;
  const double z = y / s;
  nll += 0.5 * z * z + std::log(s);
  z_sum += z;
  z2_sum += z * z;
  if (!accepted) ++rejected;
}

double InnovationStats::total_nll() const {
  double sum = 0.0;
  for (const ComponentStats& s : source) sum += s.nll;
  return sum;
}

Phase PhaseTracker::on_nav(const est::NavOutput& o) {
  const double t = o.nav.t_s;
  if (have_prev_ && t - prev_t_s_ < kPhasePeriodS) return phase_;
  const double yaw_deg = est::euler_from_quat(o.nav.q_nb).z() * 180.0 / std::numbers::pi;
  const double speed = o.nav.v_n_m_s.head<2>().norm();
  if (have_prev_) {
    const double dt = t - prev_t_s_;
    phase_ = classify_phase(std::remainder(yaw_deg - prev_yaw_deg_, 360.0) / dt, o.nav.v_n_m_s.z(),
                            (speed - prev_speed_m_s_) / dt, speed);
  }
  have_prev_ = true;
  prev_t_s_ = t;
  prev_yaw_deg_ = yaw_deg;
  prev_speed_m_s_ = speed;
  return phase_;
}

void InnovationStatsListener::on_innovation(const est::InnovationRecord& rec) {
  const auto k = static_cast<std::size_t>(rec.source);
  if (k >= kSources) return;  // zero-velocity and vehicle constraints are pseudo-measurements: not scored
  for (Eigen::Index i = 0; i < rec.result.rows; ++i) {
    const double s = rec.result.innovation_sigma(i);
    if (!(s > 0.0)) continue;  // no predicted sigma: nothing to score
    const double y = rec.result.innovation(i);
    stats_.source[k].add(y, s, rec.result.accepted);
    if (i < 3) {
      const auto c = static_cast<std::size_t>(i);
      if (have_prev_[k][c]) stats_.source[k].lag_sum += (y / s) * prev_z_[k][c];
      prev_z_[k][c] = y / s;
      have_prev_[k][c] = true;
    }
    stats_.by_phase[k][static_cast<std::size_t>(phases_.phase())].add(y, s, rec.result.accepted);
  }
}

}  // namespace sinu::diagnose
