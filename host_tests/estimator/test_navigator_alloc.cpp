// No heap allocation after init(): the whole IMU/GNSS/magnetometer loop of
// the Navigator, with every effect state, the AR model and the wavelet
// prefilter in front, counted by the global operator new.
#include <gtest/gtest.h>

#include "estimator/prefilter/wavelet_prefilter.hpp"
#include "host_tests/estimator/navigator_run.hpp"
#include "host_tests/support/alloc_counter.hpp"

namespace sinu::test {
namespace {

class NullObserver final : public est::NavObserver {
 public:
  void on_nav(const est::NavOutput& o) override { last_t = o.nav.t_s; }
  void on_innovation(const est::InnovationRecord& r) override { accepted += r.result.accepted ? 1 : 0; }
  double last_t = 0.0;
  int accepted = 0;
};

/// Every effect state, the wavelet prefilter in front; the navigator after
/// the run, and the heap allocations counted while it ran.
struct AllocRun {
  std::unique_ptr<est::Navigator> nav = std::make_unique<est::Navigator>();
  NullObserver obs;
  std::size_t allocations = 0;
};
void run_counting(est::NavigatorConfig cfg, const std::vector<est::ImuSample>& imu,
                  const std::vector<est::GnssObservation>& gnss, AllocRun& run) {
  cfg.gps_latency_s = 0.05;
  for (std::size_t e = 0; e < est::kEffectCount; ++e) cfg.effects.add(static_cast<est::Effect>(e));
  auto prefilter = est::make_wavelet_prefilter(est::wavelet::WaveletKind::Db4, 3);
  run.nav->init(cfg, &run.obs, prefilter.get());
  AllocationScope scope;
  feed(*run.nav, imu, gnss);
  run.allocations = static_cast<std::size_t>(scope.count());
}

TEST(NavigatorAlloc, LoopAllocatesNothingAfterInit) {
  const auto truth = AnalyticFlight(FlightProfile{}).sample(40.0, 200.0);
  const auto gnss = AnalyticFlight::gnss(truth, 8, 0.05, Eigen::Vector3d::Zero(), 0.5, 0.1);
  std::vector<est::ImuSample> imu;
  const Eigen::Vector3d earth_field_n_uT(20.0, 2.0, 40.0);
  for (const auto& s : truth) {
    imu.push_back(s.imu);
    imu.back().mag_b_uT = s.nav.C_nb().transpose() * earth_field_n_uT;
    imu.back().has_mag = true;
  }
  for (const auto kind : {est::NoiseModelKind::GaussMarkov, est::NoiseModelKind::AutoRegressive}) {
    est::NavigatorConfig cfg;
    cfg.noise = est::SensorNoise::defaults(kind);
    AllocRun run;
    run_counting(cfg, imu, gnss, run);
    EXPECT_EQ(run.allocations, 0u);
    EXPECT_TRUE(run.nav->aligned());
    EXPECT_GT(run.obs.accepted, 1000);  // the loop really fused (not a vacuous zero)
    EXPECT_GT(run.nav->counters().accepted[static_cast<std::size_t>(est::AidingSource::Magnetometer)], 1000u);
  }
}

// The fault paths too: a start in flight (in-motion alignment), a ground
// vehicle's constraints, a NaN, a repeated time stamp, a 3 s gap, clipping,
// a GNSS outage and a GNSS jump long enough to be reset to, a magnetometer
// disturbance that re-anchors the hard iron.
TEST(NavigatorAlloc, FaultPathsAllocateNothing) {
  const auto truth = AnalyticFlight(FlightProfile{}).sample(40.0, 400.0);
  auto gnss = AnalyticFlight::gnss(truth, 8, 0.05, Eigen::Vector3d::Zero(), 0.5, 0.1);
  const Eigen::Vector3d earth_field_n_uT(20.0, 2.0, 40.0);
  std::vector<est::ImuSample> imu;
  for (std::size_t i = 2000; i < truth.size(); ++i) {  // 50 s in: moving, no rest period
    est::ImuSample s = truth[i].imu;
    s.mag_b_uT = truth[i].nav.C_nb().transpose() * earth_field_n_uT;
    s.has_mag = true;
    if (i >= 8000 && i < 8400) s.mag_b_uT.z() += 15.0;  // a motor switched on
    if (i == 6000) s.specific_force_b_m_s2.x() = NAN;
    if (i >= 7000 && i < 7040) s.specific_force_b_m_s2.setConstant(39.2266);  // pegged
    if (i >= 9000 && i < 9120) continue;                                       // a 3 s gap
    imu.push_back(s);
    if (i == 10000) imu.push_back(s);  // the same time stamp again
  }
  std::vector<est::GnssObservation> fixes;
  for (est::GnssObservation z : gnss) {
    const double t = z.arrival_s - truth.front().nav.t_s;
    if (t > 260.0 && t < 290.0) continue;                  // outage
    if (t > 300.0 && t < 320.0) z.lat_rad += 200.0 / 6.37e6;  // a jump held off, then reset to
    fixes.push_back(z);
  }
  est::NavigatorConfig cfg;
  cfg.noise = est::SensorNoise::defaults(est::NoiseModelKind::AutoRegressive);
  cfg.vehicle = est::VehicleKind::Ground;
  cfg.recovery.jump_hold_s = 10.0;
  AllocRun run;
  run_counting(cfg, imu, fixes, run);
  EXPECT_EQ(run.allocations, 0u);
  ASSERT_TRUE(run.nav->aligned());
  const est::NavCounters& c = run.nav->counters();
  // Each path was taken (not a vacuous zero).
  EXPECT_EQ(c.imu_invalid, 1u);
  EXPECT_GE(c.imu_non_increasing, 1u);
  EXPECT_EQ(c.imu_gaps, 1u);
  EXPECT_GE(c.imu_clipped_samples, 30u);
  EXPECT_GE(c.gnss_timeouts, 1u);
  EXPECT_GE(c.position_resets, 1u);
  EXPECT_GT(c.accepted[static_cast<std::size_t>(est::AidingSource::Nonholonomic)], 100u);
  EXPECT_GE(c.mag_reanchors, 1u);
}

// Without a magnetometer, the unit mounted turned 90 deg about z: aligned on
// the GNSS course, then the in-motion alignment's check turns the solution.
TEST(NavigatorAlloc, TheCourseCheckAllocatesNothing) {
  FlightProfile gentle;  // a car's start: 0.4 m/s^2, which leaves the EKF's heading where the course put it
  gentle.cruise_m_s = 8.0;
  const auto truth = AnalyticFlight(gentle).sample(40.0, 200.0);
  const auto gnss = AnalyticFlight::gnss(truth, 8, 0.05, Eigen::Vector3d::Zero(), 0.5, 0.1);
  std::vector<est::ImuSample> imu;
  const auto turned = [](const Eigen::Vector3d& v) { return Eigen::Vector3d(v.y(), -v.x(), v.z()); };
  for (const auto& s : truth) {
    imu.push_back(s.imu);
    imu.back().specific_force_b_m_s2 = turned(s.imu.specific_force_b_m_s2);
    imu.back().angular_rate_b_rad_s = turned(s.imu.angular_rate_b_rad_s);
    imu.back().has_mag = false;
  }
  est::NavigatorConfig cfg;
  cfg.noise = est::SensorNoise::defaults(est::NoiseModelKind::AutoRegressive);
  AllocRun run;
  run_counting(cfg, imu, gnss, run);
  EXPECT_EQ(run.allocations, 0u);
  ASSERT_TRUE(run.nav->aligned());
  EXPECT_EQ(run.nav->alignment_result().heading_source, est::HeadingSource::GnssCourse);
  EXPECT_TRUE(std::isfinite(run.nav->alignment_result().course_turn_rad)) << "the check's path was not taken";
}

}  // namespace
}  // namespace sinu::test
