// sinu simulate throughput: a 30-minute 40 Hz flight (imu.csv, truth.csv,
// gps.nmea) and an 8-hour 40 Hz static session (imu.csv), written to a temp
// folder. Targets (issue 3): < 5 s and < 20 s on one core.
// Report: wall time per session; items_per_second = IMU rows per second.
#include <benchmark/benchmark.h>

#include "firmware/host/sim/simulation.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace {

void simulate(benchmark::State& state, sinu::sim::SimMode mode, double duration_s) {
  sinu::test::TempDir dir;
  sinu::sim::SimOptions o;
  o.mode = mode;
  o.seed = 1;
  o.duration_s = duration_s;
  o.out_dir = dir.path().string();
  std::uint64_t rows = 0;
  for (auto _ : state) {
    sinu::sim::SimResult r;
    sinu::dataset::Diagnostic err;
    if (!sinu::sim::run_simulation(o, r, err)) state.SkipWithError(err.to_string().c_str());
    rows += r.imu_rows;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(rows));
}

void BM_SimulateFlight30min40Hz(benchmark::State& state) { simulate(state, sinu::sim::SimMode::Flight, 1800.0); }
void BM_SimulateStatic8h40Hz(benchmark::State& state) { simulate(state, sinu::sim::SimMode::Static, 8 * 3600.0); }

}  // namespace

BENCHMARK(BM_SimulateFlight30min40Hz)->Unit(benchmark::kSecond)->Iterations(3)->UseRealTime();
BENCHMARK(BM_SimulateStatic8h40Hz)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

BENCHMARK_MAIN();
