#pragma once
// Test helper: runs the Navigator over an analytic flight and compares every
// output with the truth at the same instant.
#include <cmath>
#include <vector>

#include "estimator/nav/navigator.hpp"
#include "host_tests/estimator/analytic_flight.hpp"

namespace sinu::test {

struct RunStats {
  std::vector<double> t, pos_err_h, pos_err_v, att_err, nees;
  std::vector<double> nis_pos;
  std::size_t rejected = 0, accepted = 0;
  bool symmetric = true;
  bool positive_definite = true;
  double align_t = NAN;
};

class TruthComparer : public est::NavObserver {
 public:
  TruthComparer(const std::vector<TruthSample>& truth, double rate_hz, RunStats& s)
      : truth_(truth), rate_(rate_hz), s_(s) {}
  void on_nav(const est::NavOutput& o) override {
    const auto i = static_cast<std::size_t>(std::lround((o.nav.t_s - truth_.front().nav.t_s) * rate_));
    if (i >= truth_.size()) return;
    const est::NavState& tr = truth_[i].nav;
    if (std::isnan(s_.align_t)) s_.align_t = o.nav.t_s;
    const Eigen::Vector3d dp = position_error_ned(o.nav, tr);
    const Eigen::Vector3d dv = o.nav.v_n_m_s - tr.v_n_m_s;
    // phi with C_hat = (I - [phi x]) C: C_hat C^T = I - [phi x].
    const Eigen::Matrix3d E = o.nav.C_nb() * tr.C_nb().transpose();
    const Eigen::Vector3d phi(-(E(2, 1) - E(1, 2)) / 2, -(E(0, 2) - E(2, 0)) / 2, -(E(1, 0) - E(0, 1)) / 2);
    Eigen::Matrix<double, 9, 1> e;
    e << dp, dv, phi;
    s_.t.push_back(o.nav.t_s);
    s_.pos_err_h.push_back(dp.head<2>().norm());
    s_.pos_err_v.push_back(std::abs(dp.z()));
    s_.att_err.push_back(attitude_error_rad(o.nav.q_nb, tr.q_nb));
    s_.nees.push_back(e.dot(o.P_nav.ldlt().solve(e)));
  }
  void on_innovation(const est::InnovationRecord& r) override {
    if (r.result.accepted) {
      ++s_.accepted;
      if (r.source == est::AidingSource::GnssPosition) s_.nis_pos.push_back(r.result.nis);
    } else {
      ++s_.rejected;
    }
  }

 private:
  const std::vector<TruthSample>& truth_;
  double rate_;
  RunStats& s_;
};

/// Feeds IMU samples and GNSS epochs in arrival order.
inline void feed(est::Navigator& nav, const std::vector<est::ImuSample>& imu,
                 const std::vector<est::GnssObservation>& gnss) {
  std::size_t g = 0;
  for (const est::ImuSample& s : imu) {
    while (g < gnss.size() && gnss[g].arrival_s <= s.t_s) nav.push_gnss(gnss[g++]);
    nav.push_imu(s);
  }
  nav.flush();
}

/// One navigator run over a flight, every output scored against the truth:
/// run.stats, and run.nav for what the filter ended with.
struct ScoredRun {
  ScoredRun(const est::NavigatorConfig& cfg, const std::vector<TruthSample>& truth, double rate_hz,
            const std::vector<est::ImuSample>& imu, const std::vector<est::GnssObservation>& gnss)
      : cmp(truth, rate_hz, stats) {
    nav.init(cfg, &cmp, nullptr);
    feed(nav, imu, gnss);
  }
  RunStats stats;
  TruthComparer cmp;
  est::Navigator nav;
};

inline double rms_after(const std::vector<double>& t, const std::vector<double>& x, double t_from) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (t[i] < t_from) continue;
    sum += x[i] * x[i];
    ++n;
  }
  return n ? std::sqrt(sum / static_cast<double>(n)) : NAN;
}

}  // namespace sinu::test
