// Full calibration of an 8-hour 40 Hz 6-axis static session in memory:
// wavelet denoising, autocorrelation to 600 s, GM1, AR(1..10) by three
// methods, Allan deviation and noise terms, for all six axes (one core).
// File reading is measured separately (see docs/performance.md).
#include <benchmark/benchmark.h>

#include <random>

#include "firmware/host/calibration/calibration_run.hpp"

namespace {

sinu::calibration::StaticSession make_session() {
  constexpr double kRateHz = 40.0;
  constexpr std::size_t kSamples = static_cast<std::size_t>(8 * 3600 * kRateHz);
  sinu::calibration::StaticSession s;
  s.dataset = "synthetic";
  s.dt_s = 1.0 / kRateHz;
  s.duration_s = static_cast<double>(kSamples - 1) * s.dt_s;
  s.rows = kSamples;
  std::mt19937_64 rng(1);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (auto& axis : s.imu) {
    axis.resize(kSamples);
    double p1 = 0.0, p2 = 0.0, walk = 0.0;
    for (double& v : axis) {
      const double p = 1.99 * p1 - 0.9925 * p2 + 1e-4 * normal(rng);  // periodic-random
      p2 = p1;
      p1 = p;
      walk += 1e-6 * normal(rng);
      v = 0.01 * normal(rng) + p + walk;
    }
  }
  for (auto& axis : s.mag) axis.assign(kSamples / 4, 40.0);
  return s;
}

void BM_Calibrate8h40Hz6Axis(benchmark::State& state) {
  const sinu::calibration::StaticSession session = make_session();
  sinu::calibration::Denoiser denoiser;
  std::string why;
  if (!sinu::calibration::make_wavelet_denoiser("db4", 3, denoiser, why)) {
    state.SkipWithError(why.c_str());
    return;
  }
  for (auto _ : state) {
    auto result = sinu::calibration::calibrate_session(session, denoiser, sinu::calibration::ModelChoice{});
    benchmark::DoNotOptimize(result);
  }
}
BENCHMARK(BM_Calibrate8h40Hz6Axis)->Unit(benchmark::kSecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
