// No heap allocation after init(): the whole IMU/GNSS loop of the Navigator,
// with every effect state and the AR model, counted by the global operator new.
#include <gtest/gtest.h>

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
  for (const auto& s : truth) imu.push_back(s.imu);
  for (const auto kind : {est::NoiseModelKind::GaussMarkov, est::NoiseModelKind::AutoRegressive}) {
    est::NavigatorConfig cfg;
    cfg.noise = est::SensorNoise::defaults(kind);
    cfg.gps_latency_s = 0.05;
    for (std::size_t e = 0; e < est::kEffectCount; ++e) cfg.effects.add(static_cast<est::Effect>(e));
    NullObserver obs;
    auto nav = std::make_unique<est::Navigator>();
    nav->init(cfg, &obs, nullptr);
    AllocationScope scope;
    feed(*nav, imu, gnss);
    EXPECT_EQ(scope.count(), 0u);
    EXPECT_TRUE(nav->aligned());
    EXPECT_GT(obs.accepted, 1000);  // the loop really fused (not a vacuous zero)
  }
}

}  // namespace
}  // namespace sinu::test
