// EKF predict and update cost per state-vector size, and Navigator throughput
// (IMU samples per second through alignment, INS, EKF and GNSS fusion).
#include <benchmark/benchmark.h>

#include <memory>

#include "estimator/ekf/aiding/gnss_position/gnss_position.hpp"
#include "estimator/nav/navigator.hpp"
#include "host_tests/estimator/navigator_run.hpp"

namespace {

using namespace sinu;

est::SensorNoise noise_of_order(Eigen::Index p) {
  est::SensorNoise n = est::SensorNoise::defaults(p == 0 ? est::NoiseModelKind::GaussMarkov : est::NoiseModelKind::AutoRegressive);
  if (p > 0) {
    for (auto& a : n.ar) {
      a.order = p;
      a.a = {1.0, -0.9, 0.05, 0.02, 0.01};
      a.variance = 1e-6;
    }
  }
  return n;
}

// range(0): 0 = GM (15 states), p = AR(p); range(1): 1 = every effect on
void setup(const benchmark::State& s, est::ErrorStateFilter& f, est::NavState& nav) {
  est::EffectSet eff;
  if (s.range(1)) {
    for (std::size_t e = 0; e < est::kEffectCount; ++e) eff.add(static_cast<est::Effect>(e));
  }
  const est::SensorNoise n = noise_of_order(s.range(0));
  f.init(est::StateLayout::make(n.order(), eff), n, est::EffectTuning{}, est::NavUncertainty{});
  nav.lat_rad = 0.7;
  nav.h_m = 100.0;
  nav.v_n_m_s = {40.0, 3.0, -1.0};
}

void BM_Predict(benchmark::State& s) {
  est::ErrorStateFilter f;
  est::NavState nav;
  setup(s, f, nav);
  est::PredictInput in;
  in.nav = &nav;
  in.specific_force_b_m_s2 = {0.3, 0.1, -9.8};
  in.angular_rate_b_rad_s = {0.01, 0.02, 0.05};
  in.specific_force_n_m_s2 = {0.3, 0.1, -9.8};
  in.dt_s = 0.025;
  for (auto _ : s) {
    f.predict(in);
    benchmark::DoNotOptimize(f.P()(0, 0));
  }
  s.counters["states"] = static_cast<double>(f.layout().dim);
}

void BM_GnssPositionUpdate(benchmark::State& s) {
  est::ErrorStateFilter f;
  est::NavState nav;
  setup(s, f, nav);
  est::GnssObservation z;
  z.has_position = true;
  z.lat_rad = nav.lat_rad;
  z.h_m = nav.h_m;
  est::StateVec dx;
  const est::StateMat P0 = f.P();
  for (auto _ : s) {
    f.P() = P0;  // same prior every time (the copy is part of the figure, ~1-5% of it)
    const est::Measurement m = est::gnss_position_measurement(f, nav, 0.0, z, 5.0);
    const est::UpdateResult r = est::fuse_measurement(f.P(), dx, m);
    benchmark::DoNotOptimize(r.nis);
  }
  s.counters["states"] = static_cast<double>(f.layout().dim);
}

BENCHMARK(BM_Predict)->Args({0, 0})->Args({3, 0})->Args({4, 1})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GnssPositionUpdate)->Args({0, 0})->Args({3, 0})->Args({4, 1})->Unit(benchmark::kMicrosecond);

class Null final : public est::NavObserver {
 public:
  void on_nav(const est::NavOutput& o) override { benchmark::DoNotOptimize(o.nav.h_m); }
  void on_innovation(const est::InnovationRecord&) override {}
};

void BM_NavigatorThroughput(benchmark::State& s) {
  static const auto truth = sinu::test::AnalyticFlight(sinu::test::FlightProfile{}).sample(40.0, 600.0);
  static const auto gnss = sinu::test::AnalyticFlight::gnss(truth, 8, 0.05, Eigen::Vector3d::Zero(), 0.5, 0.1);
  static const auto imu = [] {
    std::vector<est::ImuSample> v;
    for (const auto& t : truth) v.push_back(t.imu);
    return v;
  }();
  Null obs;
  for (auto _ : s) {
    est::NavigatorConfig cfg;
    cfg.noise = noise_of_order(s.range(0));
    cfg.gps_latency_s = 0.05;
    auto nav = std::make_unique<est::Navigator>();
    nav->init(cfg, &obs, nullptr);
    sinu::test::feed(*nav, imu, gnss);
  }
  s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations()) * static_cast<std::int64_t>(imu.size()));
  // Its whole memory: fixed-size, allocated once (the zero-allocation tests prove nothing more is).
  s.counters["navigator_KiB"] = static_cast<double>(sizeof(est::Navigator)) / 1024.0;
}
BENCHMARK(BM_NavigatorThroughput)->Arg(0)->Arg(3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
