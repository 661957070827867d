// The navigator's own fault handling on analytic flights (perfect sensors, so
// every error seen is the fault's): what a real log taught. uav_log171 has a
// 2-s gap in every message at arming, and its first IMU sample after the gap
// reads -3.7 m/s^2 where gravity is -9.4: bridged by a straight line, that one
// sample made 5 m/s of vertical velocity; the GPS latency state took the
// misfit (0.04 -> 0.36 s), beyond the delayed horizon (0.3 s), so every later
// epoch was "late", never fused, and the summary still said "ok". Now the gap
// holds its last sample, the latency is not learnt right after a gap, the
// horizon grows with the latency estimate, and unusable fixes are a loss.
#include <gtest/gtest.h>

#include "host_tests/estimator/navigator_run.hpp"

namespace sinu::test {
namespace {

constexpr double kRate = 40.0;
constexpr double kLatency = 0.05;

est::NavigatorConfig config_with_latency_state() {
  est::NavigatorConfig cfg;
  cfg.effects.add(est::Effect::AccelBias);
  cfg.effects.add(est::Effect::GyroBias);
  cfg.effects.add(est::Effect::GpsLatency);
  cfg.gps_latency_s = kLatency;
  return cfg;
}

std::vector<est::ImuSample> imu_of(const std::vector<TruthSample>& truth) {
  std::vector<est::ImuSample> imu;
  imu.reserve(truth.size());
  for (const auto& s : truth) imu.push_back(s.imu);
  return imu;
}

/// Records the latest output and the velocity error right after a given time.
class Watch : public est::NavObserver {
 public:
  Watch(const std::vector<TruthSample>& truth, double t_probe) : truth_(truth), t_probe_(t_probe) {}
  void on_nav(const est::NavOutput& o) override {
    last_flags = o.flags;
    all_flags |= o.flags;
    if (o.flags & est::nav_flag::kLost) lost_seen = true;
    if (!probed && o.nav.t_s >= t_probe_) {
      const auto i = static_cast<std::size_t>(std::lround((o.nav.t_s - truth_.front().nav.t_s) * kRate));
      velocity_error_at_probe_m_s = (o.nav.v_n_m_s - truth_[i].nav.v_n_m_s).norm();
      probed = true;
    }
  }
  void on_innovation(const est::InnovationRecord&) override {}
  std::uint32_t last_flags = 0, all_flags = 0;
  bool lost_seen = false, probed = false;
  double velocity_error_at_probe_m_s = NAN;

 private:
  const std::vector<TruthSample>& truth_;
  double t_probe_;
};

TEST(NavigatorFaults, AGapEndingOnATransientIsBridgedByTheLastSampleAndTheLatencyStaysPut) {
  const auto truth = AnalyticFlight(FlightProfile{}).sample(kRate, 400.0);
  const auto gnss = AnalyticFlight::gnss(truth, 8, kLatency, Eigen::Vector3d::Zero(), 0.5, 0.1);
  const double t0 = truth.front().nav.t_s;
  const double gap_from = t0 + 250.0, gap_to = gap_from + 2.0;  // in flight, after turns
  std::vector<est::ImuSample> imu;
  for (const est::ImuSample& s : imu_of(truth)) {
    if (s.t_s > gap_from && s.t_s < gap_to) continue;
    imu.push_back(s);
  }
  // The first sample after the gap: 5.7 m/s^2 off in z, as on the real log.
  for (est::ImuSample& s : imu)
    if (s.t_s >= gap_to) {
      s.specific_force_b_m_s2.z() += 5.7;
      break;
    }
  Watch watch(truth, gap_to);
  est::Navigator nav;
  nav.init(config_with_latency_state(), &watch, nullptr);
  feed(nav, imu, gnss);
  ASSERT_TRUE(watch.probed);
  EXPECT_EQ(nav.counters().imu_gaps, 1u);
  // Holding the last sample over 2 s of a coordinated turn: the velocity
  // error is the unmodelled change of the specific force over the gap (a few
  // tenths of m/s^2 here), not the transient's 5.7 m/s^2 x 1 s = 5.7 m/s that
  // the straight line to it gave. 1.5 m/s bounds the first, excludes the second.
  EXPECT_LT(watch.velocity_error_at_probe_m_s, 1.5);
  // The latency is frozen while the acceleration is unknown: it ends where the
  // same flight without the gap leaves it (within 5 ms; the transient moved
  // it by 0.3 s before), and no epoch is late.
  Watch clean_watch(truth, 1e300);
  est::Navigator clean;
  clean.init(config_with_latency_state(), &clean_watch, nullptr);
  feed(clean, imu_of(truth), gnss);
  EXPECT_NEAR(nav.filter().gps_latency_s(), clean.filter().gps_latency_s(), 0.005);
  EXPECT_EQ(nav.counters().gnss_late, 0u);
  EXPECT_FALSE(watch.lost_seen);
}

TEST(NavigatorFaults, AReceiverSlowerThanAssumedIsLearntAndTheHorizonFollowsIt) {
  // Fixes valid 0.45 s before they arrive (a slow receiver, a long serial
  // path), the unit told 0.05 s and a 0.3-s horizon: the latency estimate
  // climbs to the truth and the delayed horizon grows with it (latency +
  // 0.1 s), so the epochs keep being fused at their time of validity; before,
  // the horizon was fixed and the estimate beyond it made every epoch late.
  const auto truth = AnalyticFlight(FlightProfile{}).sample(kRate, 400.0);
  const auto gnss = AnalyticFlight::gnss(truth, 8, 0.45, Eigen::Vector3d::Zero(), 0.5, 0.1);
  Watch watch(truth, 1e300);
  est::Navigator nav;
  est::NavigatorConfig cfg = config_with_latency_state();
  nav.init(cfg, &watch, nullptr);
  feed(nav, imu_of(truth), gnss);
  // Beyond the old fixed horizon (0.3 s): measured 0.38 s. The analytic
  // flight's long straight legs leave the latency weakly observable (only
  // accelerations show it), and it reads ~15 % short here at any value (0.2 s
  // reads 0.16 s, with or without this change); the simulator's flights give
  // it within 0.02 s (Diagnose.TheDefaultModelEstimatesAHiddenGpsLatency).
  EXPECT_GT(nav.filter().gps_latency_s(), 0.33);
  EXPECT_LT(nav.filter().gps_latency_s(), 0.50);
  // Late epochs only while the horizon grows (a few), out of ~2000.
  const auto late = nav.counters().gnss_late;
  const auto fused = nav.counters().accepted[static_cast<std::size_t>(est::AidingSource::GnssPosition)] +
                     nav.counters().rejected[static_cast<std::size_t>(est::AidingSource::GnssPosition)];
  EXPECT_LT(late, fused / 100 + 1) << "late " << late << " of " << fused;
  EXPECT_FALSE(watch.lost_seen);
}

TEST(NavigatorFaults, FixesThatArriveTooLateToBeFusedAreALossNotAnOk) {
  // From 200 s on, every fix is handed to the navigator 2 s after the arrival
  // time it is stamped with (a stalled reader thread): by then the delayed
  // horizon (0.3 s) has passed its time of validity, and none can be fused.
  const auto truth = AnalyticFlight(FlightProfile{}).sample(kRate, 260.0);
  const auto gnss = AnalyticFlight::gnss(truth, 8, kLatency, Eigen::Vector3d::Zero(), 0.5, 0.1);
  const double t_late = truth.front().nav.t_s + 200.0;
  est::NavigatorConfig cfg;
  cfg.gps_latency_s = kLatency;
  Watch watch(truth, 1e300);
  est::Navigator nav;
  nav.init(cfg, &watch, nullptr);
  std::size_t g = 0;
  for (const est::ImuSample& s : imu_of(truth)) {
    while (g < gnss.size()) {
      const double handed_at = gnss[g].arrival_s + (gnss[g].arrival_s >= t_late ? 2.0 : 0.0);
      if (handed_at > s.t_s) break;
      nav.push_gnss(gnss[g++]);
    }
    nav.push_imu(s);
  }
  nav.flush();
  EXPECT_GT(nav.counters().gnss_late, 200u);  // 60 s at 5 Hz, every one of them
  EXPECT_TRUE(watch.lost_seen) << "fixes arriving and none fused for 10 s is a loss";
  EXPECT_TRUE(watch.last_flags & est::nav_flag::kLost);
}

}  // namespace
}  // namespace sinu::test
