// sinu replay throughput, end to end (issue 6): a simulated 50-minute 40 Hz
// flight read from its dataset folder (imu.csv, gps.nmea, truth.csv), the
// calibration's wavelet denoiser, INS/EKF, nav.csv / innovations.csv /
// summary.json written. The calibration comes from a 1-hour bench session of
// the same unit, as a user would make it. Target: AR(3) in < 2 s on one core.
// items_per_second = IMU samples per second.
#include <benchmark/benchmark.h>

#include "firmware/host/calibration/calib_json.hpp"
#include "firmware/host/calibration/calibration_run.hpp"
#include "firmware/host/replay/replay_files.hpp"
#include "firmware/host/sim/simulation.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace {

struct Flight {
  sinu::test::TempDir dir;
  std::string dataset, calib;
  Flight() {
    sinu::sim::SimOptions o;
    o.seed = 11;
    sinu::sim::SimResult r;
    sinu::dataset::Diagnostic err;
    o.mode = sinu::sim::SimMode::Flight;
    o.duration_s = 3000.0;
    o.out_dir = dataset = (dir.path() / "flight").string();
    sinu::sim::run_simulation(o, r, err);
    o.mode = sinu::sim::SimMode::Static;
    o.duration_s = 3600.0;
    o.out_dir = (dir.path() / "bench").string();
    sinu::sim::run_simulation(o, r, err);
    sinu::calibration::StaticSession session;
    sinu::calibration::load_static_session(o.out_dir, session, err);
    sinu::calibration::CalibrationRun run;
    std::string why;
    sinu::calibration::make_wavelet_denoiser("db4", 3, run.denoiser, why);
    run.sessions.push_back(sinu::calibration::calibrate_session(session, run.denoiser, sinu::calibration::ModelChoice{}));
    calib = (dir.path() / "calib.json").string();
    sinu::calibration::write_calib_json(run, calib, why);
  }
};

const Flight& flight() {
  static const Flight f;
  return f;
}

/// `full`: the default options (replay::default_effects and the magnetometer);
/// else the bare model of issue 6's target (no effect states, no magnetometer).
void replay(benchmark::State& state, sinu::est::NoiseModelKind kind, bool full) {
  const Flight& f = flight();
  sinu::replay::ReplayOptions opt;
  opt.in_dir = f.dataset;
  opt.unit.calib_path = f.calib;
    const std::string out_dir = (f.dir.path() / "out").string();
  opt.unit.calib.kind = kind;
  opt.unit.use_mag = full;
  if (!full) opt.unit.effects = {};
  std::uint64_t samples = 0;
  for (auto _ : state) {
    sinu::replay::ReplayResult totals;
    std::string error;
    if (!sinu::replay::replay_to_folder(opt, out_dir, 10.0, totals, error)) state.SkipWithError(error.c_str());
    samples += totals.imu_samples;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(samples));
}

// Bare: GM1 15 states, Burg AR(3) 27 states (issue 6's configuration).
void BM_Replay50minGmBare(benchmark::State& s) { replay(s, sinu::est::NoiseModelKind::GaussMarkov, false); }
void BM_Replay50minAr3Bare(benchmark::State& s) { replay(s, sinu::est::NoiseModelKind::AutoRegressive, false); }
// Default options (what `sinu replay --calib C` runs): + accel and gyro turn-on
// bias, GPS position bias and latency, magnetometer (Earth field, hard iron):
// GM1 31 states, Burg AR(3) 43.
void BM_Replay50minGm(benchmark::State& s) { replay(s, sinu::est::NoiseModelKind::GaussMarkov, true); }
void BM_Replay50minAr3(benchmark::State& s) { replay(s, sinu::est::NoiseModelKind::AutoRegressive, true); }

}  // namespace

BENCHMARK(BM_Replay50minGmBare)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_Replay50minAr3Bare)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_Replay50minGm)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_Replay50minAr3)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK_MAIN();
