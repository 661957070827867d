#include "firmware/host/replay/nav_metrics.hpp"

#include <cmath>

#include "estimator/earth/wgs84.hpp"

namespace sinu::replay {

void chi2_bounds_95(int dof, double& lo, double& hi) {
  // scipy.stats.chi2.ppf([0.025, 0.975], dof), dof = 1..9
  static constexpr double kLo[] = {0.000982, 0.0506, 0.2158, 0.4844, 0.8312, 1.2373, 1.6899, 2.1797, 2.7004};
  static constexpr double kHi[] = {5.0239, 7.3778, 9.3484, 11.1433, 12.8325, 14.4494, 16.0128, 17.5345, 19.0228};
  const auto i = static_cast<std::size_t>(std::clamp(dof, 1, 9) - 1);
  lo = kLo[i];
  hi = kHi[i];
}

void ChiStats::add(double v, double lo, double hi) {
  if (!std::isfinite(v)) return;
  ++count;
  sum += v;
  if (v >= lo && v <= hi) ++inside;
}

void NavMetrics::init(const std::vector<Outage>& list, const Eigen::Vector3d& lever_arm_b_m) {
  lever_arm_b_m_ = lever_arm_b_m;
  outages.clear();
  outages.reserve(list.size());
  for (const Outage& o : list) outages.push_back({o, 0.0, 0, 0});
}

void NavMetrics::add_gnss(const GnssPoint& fix) {
  if (pending_gnss_.full()) pending_gnss_.pop();  // no truth near it: not scored
  pending_gnss_.push(fix);
}

void NavMetrics::score_gnss(const TruthPoint& a, const TruthPoint& b) {
  namespace w = est::wgs84;
  while (!pending_gnss_.empty() && pending_gnss_.front().t_s <= b.t_s) {
    const GnssPoint g = pending_gnss_.front();
    pending_gnss_.pop();
    if (g.t_s < a.t_s || b.t_s - a.t_s > 1.0) continue;  // outside truth, or truth has a gap here
    const double f = b.t_s > a.t_s ? (g.t_s - a.t_s) / (b.t_s - a.t_s) : 0.0;
    const double lat = a.lat_rad + f * (b.lat_rad - a.lat_rad);
    const double lon = w::lon_between_rad(a.lon_rad, b.lon_rad, f);
    const double h = a.h_m + f * (b.h_m - a.h_m);
    const Eigen::Vector3d lever_n = a.has_att ? Eigen::Vector3d(a.q_nb * lever_arm_b_m_) : Eigen::Vector3d::Zero();
    const Eigen::Vector3d dp((g.lat_rad - lat) * (w::meridian_radius_m(lat) + h) - lever_n.x(),
                             w::lon_difference_rad(g.lon_rad, lon) * (w::transverse_radius_m(lat) + h) * std::cos(lat) - lever_n.y(),
                             -(g.h_m - h) - lever_n.z());
    // The truth's velocity here: a fix valid delta later than assumed errs by dp + v delta.
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    if (b.t_s > a.t_s) {
      v = Eigen::Vector3d((b.lat_rad - a.lat_rad) * (w::meridian_radius_m(lat) + h),
                          w::lon_difference_rad(b.lon_rad, a.lon_rad) * (w::transverse_radius_m(lat) + h) * std::cos(lat),
                          -(b.h_m - a.h_m)) / (b.t_s - a.t_s);
    }
    ++gnss_compared;
    gnss_h.add(dp.head<2>(), v.head<2>());
    gnss_v.add(dp.tail<1>(), v.tail<1>());
  }
}

void NavMetrics::add_truth(const TruthPoint& tr, const est::NavState& nav, const Eigen::Matrix<double, 9, 9>& P) {
  namespace w = est::wgs84;
  if (have_prev_truth_) score_gnss(prev_truth_, tr);
  if (!have_prev_truth_) first_truth_t_s_ = tr.t_s;
  prev_truth_ = tr;
  have_prev_truth_ = true;
  const Eigen::Vector3d dp((nav.lat_rad - tr.lat_rad) * (w::meridian_radius_m(tr.lat_rad) + tr.h_m),
                           w::lon_difference_rad(nav.lon_rad, tr.lon_rad) * (w::transverse_radius_m(tr.lat_rad) + tr.h_m) * std::cos(tr.lat_rad),
                           -(nav.h_m - tr.h_m));
  const double err_h = dp.head<2>().norm();
  ++compared;
  sum_h2 += err_h * err_h;
  sum_v2 += dp.z() * dp.z();
  Eigen::Matrix<double, 9, 1> e = Eigen::Matrix<double, 9, 1>::Zero();
  e.head<3>() = dp;
  int dof = 3;
  if (tr.has_vel) {
    const Eigen::Vector3d dv = nav.v_n_m_s - tr.v_n;
    ++compared_vel;
    sum_vel2 += dv.squaredNorm();
    e.segment<3>(3) = dv;
    dof = 6;
  }
  if (tr.has_att && tr.has_vel) {
    const double ang = Eigen::AngleAxisd(nav.q_nb * tr.q_nb.conjugate()).angle();
    ++compared_att;
    sum_att2 += ang * ang;
    const Eigen::Matrix3d E = nav.C_nb() * tr.q_nb.toRotationMatrix().transpose();  // = I - [phi x]
    e.segment<3>(6) = Eigen::Vector3d(E(1, 2) - E(2, 1), E(2, 0) - E(0, 2), E(0, 1) - E(1, 0)) / 2.0;
    dof = 9;
  }
  const auto n = static_cast<Eigen::Index>(dof);
  const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 9, 1> ev = e.head(n);
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 9, 9> Pn = P.topLeftCorner(n, n);
  double lo = 0.0, hi = 0.0;
  chi2_bounds_95(dof, lo, hi);
  nees_dof = dof;
  const double nees_value = ev.dot(Pn.ldlt().solve(ev));
  nees.add(nees_value, lo, hi);
  if (tr.t_s >= first_truth_t_s_ + kSettleS) nees_settled.add(nees_value, lo, hi);
  for (OutageDrift& o : outages) {
    if (tr.t_s >= o.window.start_s && tr.t_s <= o.window.start_s + o.window.duration_s) {
      o.max_drift_h_m = std::max(o.max_drift_h_m, err_h);
      ++o.points;
    }
  }
}

void NavMetrics::add_innovation(const est::InnovationRecord& rec) {
  if (!rec.result.accepted) return;
  double lo = 0.0, hi = 0.0;
  chi2_bounds_95(static_cast<int>(rec.result.rows), lo, hi);
  nis[static_cast<std::size_t>(rec.source)].add(rec.result.nis, lo, hi);
}

}  // namespace sinu::replay
