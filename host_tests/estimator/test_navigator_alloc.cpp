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
    cfg.gps_latency_s = 0.05;
    for (std::size_t e = 0; e < est::kEffectCount; ++e) cfg.effects.add(static_cast<est::Effect>(e));
    NullObserver obs;
    auto nav = std::make_unique<est::Navigator>();
    auto prefilter = est::make_wavelet_prefilter(est::wavelet::WaveletKind::Db4, 3);
    nav->init(cfg, &obs, prefilter.get());
    AllocationScope scope;
    feed(*nav, imu, gnss);
    EXPECT_EQ(scope.count(), 0u);
    EXPECT_TRUE(nav->aligned());
    EXPECT_GT(obs.accepted, 1000);  // the loop really fused (not a vacuous zero)
    EXPECT_GT(nav->counters().accepted[static_cast<std::size_t>(est::AidingSource::Magnetometer)], 1000u);
  }
}

}  // namespace
}  // namespace sinu::test
