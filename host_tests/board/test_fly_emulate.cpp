// sinu fly --emulate: the board's fly loop, unchanged, against the ICM-20948
// emulator on a fake I2C bus, a fake data-ready line and the GPS bytes
// through a pty. What the user relies on before flashing: the board computes
// what `sinu replay` computes from the same data, what it records replays to
// the same output bit for bit, and it survives and flags the faults of a
// real bus and receiver.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstdio>

#include "estimator/nav/nav_health.hpp"
#include "host_tests/board/fly_flight.hpp"
#include "host_tests/support/dataset_faults.hpp"
#include "host_tests/support/read_json.hpp"
#include "host_tests/support/nav_error.hpp"
#include "host_tests/support/replay_helpers.hpp"
#include "host_tests/support/run_process.hpp"

namespace sinu::test {
namespace {

namespace f = est::nav_flag;

// The emulated board stamps every sample and every GPS byte with the
// dataset's own time, so the navigator sees the same numbers in the same
// order as from the dataset: equal to the last bit in practice; 1e-9 (of
// degrees, metres, m/s, flags) is the contract, far below any physical
// resolution (1e-9 deg of latitude is 0.1 mm).
constexpr double kSameOutput = 1e-9;

ProcessResult fly(const std::vector<std::string>& args) {
  std::vector<std::string> a = {"fly", "--health-period", "0"};
  a.insert(a.end(), args.begin(), args.end());
  return run_sinu(a);
}

// sscanf from the last occurrence of `anchor` in `text` (the end-of-run line
// comes last); returns the number of fields read, -1 if the anchor is absent.
template <typename... Fields>
int scan_from(const std::string& text, const char* anchor, const char* format, Fields*... fields) {
  const std::size_t at = text.rfind(anchor);
  return at == std::string::npos ? -1 : std::sscanf(text.c_str() + at, format, fields...);
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6f", v);
  return buf;
}

TEST(FlyEmulate, TheWholeFlightAtFullSpeedIsTheReplayAndItsRecordingReplaysBitForBit) {
  TempDir tmp;
  const FlyFlight fl = make_fly_flight(tmp, "flight", 1800, 11);  // the simulator's default 30-min flight
  const std::string config = write_fly_config(tmp, "fly"), log = tmp.file("fly_nav.csv"), raw = tmp.file("fly.raw");
  const ProcessResult r = fly({"--config", config, "--emulate", fl.quantised, "--speed", "0", "--record", raw});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("solution ok"), std::string::npos) << r.err;

  ASSERT_EQ(run_sinu({"replay", "--in", fl.quantised, "--out", tmp.file("replay"), "--quiet"}).exit_code, 0);
  const CsvNumbers flown = read_csv_numbers(log), replayed = read_csv_numbers(tmp.file("replay") + "/nav.csv");
  EXPECT_EQ(flown.header, replayed.header);
  ASSERT_GT(flown.rows.size(), 17000u) << "10 Hz over the flight after alignment";
  EXPECT_EQ(flown.rows.size(), replayed.rows.size());
  const CsvDifference d = compare_rows(flown, replayed, 1e300);
  EXPECT_EQ(d.rows, flown.rows.size()) << "every row at the same time";
  EXPECT_LE(d.max_abs, kSameOutput);

  // The recording the flight wrote, replayed: what the board computed.
  ASSERT_EQ(run_sinu({"replay", "--in", raw, "--out", tmp.file("from_raw"), "--quiet"}).exit_code, 0);
  EXPECT_EQ(read_file(log), read_file(tmp.file("from_raw") + "/nav.csv"));
}

// --speed 1 paces the emulator on the wall clock: 60 s of flight take 60 s,
// and the loop, now waiting for each edge like the board, still computes
// the replay's solution; --stats reports its time per sample.
TEST(FlyEmulate, SixtySecondsInRealTimeAreTheReplayToo) {
  TempDir tmp;
  const FlyFlight fl = make_fly_flight(tmp, "flight", 300, 12);
  const std::string config = write_fly_config(tmp, "fly"), log = tmp.file("fly_nav.csv");
  const auto start = std::chrono::steady_clock::now();
  const ProcessResult r = fly({"--config", config, "--emulate", fl.quantised, "--speed", "1", "--duration", "60", "--stats"});
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // 60 s of board time from the driver's start (1 s before the first sample), paced;
  // start-up and the flush add little.
  EXPECT_GT(wall_s, 59.0);
  EXPECT_LT(wall_s, 75.0);
  double median_us = 0.0, worst_us = 0.0;
  int samples = 0;
  ASSERT_EQ(scan_from(r.out, "median ", "median %lf us, worst %lf us, %d samples", &median_us, &worst_us, &samples), 3)
      << r.out;
  EXPECT_GT(median_us, 0.0);
  EXPECT_GE(worst_us, median_us);
  EXPECT_NEAR(samples, 59.0 * 40.0, 40.0) << "every sample of the minute measured";

  ASSERT_EQ(run_sinu({"replay", "--in", fl.quantised, "--out", tmp.file("replay"), "--quiet"}).exit_code, 0);
  const CsvNumbers flown = read_csv_numbers(log), replayed = read_csv_numbers(tmp.file("replay") + "/nav.csv");
  ASSERT_GT(flown.rows.size(), 100u);
  // The last second of the flown log was flushed at the stop without the
  // fixes that arrive later: compare up to a second before it.
  const double t_end = flown.rows.back()[0];
  EXPECT_NEAR(t_end, fl.t0_s + 59.0, 1.0);
  const CsvDifference d = compare_rows(flown, replayed, t_end - 1.0);
  EXPECT_GE(d.rows, flown.rows.size() - 12);
  EXPECT_LE(d.max_abs, kSameOutput);
}

// Mid-flight: the I2C bus stops answering for 2 s, the GPS sends garbage for
// 5 s, the data-ready edges are lost for 3 s; each recovers. No crash, the
// counters and flags say what happened, and the horizontal error is back
// within 2x its fault-free value 30 s after each fault.
TEST(FlyEmulate, FaultsMidFlightAreSurvivedFlaggedAndTheSolutionReconverges) {
  TempDir tmp;
  const FlyFlight fl = make_fly_flight(tmp, "flight", 700, 13);
  const double i2c = fl.t0_s + 300.0, gps = fl.t0_s + 400.0, drdy = fl.t0_s + 500.0;
  const std::string faults = "i2c-stop:" + fmt(i2c) + ":2,gps-garbage:" + fmt(gps) + ":5,drdy-lost:" + fmt(drdy) + ":3";
  const std::string config = write_fly_config(tmp, "fly"), raw = tmp.file("fly.raw");
  const ProcessResult r = fly({"--config", config, "--emulate", fl.quantised, "--speed", "0", "--fault", faults, "--record", raw});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string base_config = write_fly_config(tmp, "base");
  ASSERT_EQ(fly({"--config", base_config, "--emulate", fl.quantised, "--speed", "0"}).exit_code, 0);

  // Counters: "... IMU samples (P polled, E I2C errors, R re-inits; ...); GPS C sentences corrupt, G garbage bytes; ..."
  int polled = 0, i2c_errors = 0, reinits = 0, garbage = 0;
  ASSERT_EQ(scan_from(r.err, "samples (", "samples (%d polled, %d I2C errors, %d re-inits", &polled, &i2c_errors, &reinits), 3)
      << r.err;
  EXPECT_GT(polled, 100) << "3 s of samples read by polling";
  EXPECT_GT(i2c_errors, 0);
  EXPECT_GE(reinits, 1) << "the driver re-initialised the chip after the bus came back";
  ASSERT_EQ(scan_from(r.err, "corrupt, ", "corrupt, %d garbage bytes", &garbage), 1) << r.err;
  EXPECT_GT(garbage, 1000) << "5 s of a 5 Hz receiver's bytes";

  const ErrorSeries faulty = error_series(tmp.file("fly_nav.csv"), fl.dir + "/truth.csv");
  const ErrorSeries clean = error_series(tmp.file("base_nav.csv"), fl.dir + "/truth.csv");
  EXPECT_TRUE(flags_between(faulty, i2c, i2c + 3.0) & f::kImuGap) << "the 2 s without samples is a gap";
  EXPECT_TRUE(flags_between(faulty, gps + 2.0, gps + 6.0) & f::kGnssTimeout) << "no fix: dead reckoning, flagged";
  EXPECT_FALSE(flags_between(clean, gps + 2.0, gps + 6.0) & f::kGnssTimeout);
  for (const auto& [name, end] : {std::pair{"i2c", i2c + 2.0}, {"gps", gps + 5.0}, {"drdy", drdy + 3.0}}) {
    // 1 m of slack: the fault-free error itself is ~0.5-1 m and its 30-s RMS varies.
    const double after = rms_between(faulty, end + 30.0, end + 60.0), base = rms_between(clean, end + 30.0, end + 60.0);
    EXPECT_LE(after, 2.0 * base + 1.0) << name << ": " << after << " m against " << base << " m fault-free";
    EXPECT_LT(max_between(faulty, end - 10.0, end + 30.0), 20.0) << name << ": not lost meanwhile";
  }
  // The recording holds the faults as the loop met them: it replays to the same solution.
  ASSERT_EQ(run_sinu({"replay", "--in", raw, "--out", tmp.file("from_raw"), "--quiet"}).exit_code, 0);
  EXPECT_EQ(read_file(tmp.file("fly_nav.csv")), read_file(tmp.file("from_raw") + "/nav.csv"));
}

// The board keeps its state file as `sinu replay --state-file` does (the same
// solution, saved at the same instants: the same numbers), and a board that
// restarts 20 s after its last save, in the air, starts from it and says so.
TEST(FlyEmulate, KeepsTheStateFileAndARestartInTheAirStartsFromIt) {
  TempDir tmp;
  const FlyFlight fl = make_fly_flight(tmp, "flight", 300, 13);
  inject_faults(fl.quantised, tmp.file("before"), {KeepLeadingSeconds{200.0}});
  inject_faults(fl.quantised, tmp.file("after"), {DropLeadingSeconds{220.0}});
  const std::string config = write_fly_config(tmp, "fly"), state = tmp.file("fly_state.json");
  ProcessResult r = fly({"--config", config, "--emulate", tmp.file("before"), "--speed", "0"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string replay_state = tmp.file("replay_state.json");
  ASSERT_EQ(run_sinu({"replay", "--in", tmp.file("before"), "--quiet", "--out", tmp.file("replay"), "--state-file",
                      replay_state}).exit_code, 0);
  const nlohmann::json board = read_json(state), host = read_json(replay_state);
  EXPECT_EQ(board["saved_utc_ms"], host["saved_utc_ms"]);
  ASSERT_EQ(board["effects"].size(), host["effects"].size());
  for (const auto& [name, e] : host["effects"].items()) {
    for (std::size_t i = 0; i < e["estimate"].size(); ++i) {
      EXPECT_NEAR(board["effects"][name]["estimate"][i].get<double>(), e["estimate"][i].get<double>(),
                  kSameOutput * (1.0 + std::abs(e["estimate"][i].get<double>()))) << name;
    }
  }
  r = run_sinu({"fly", "--health-period", "0.001", "--config", config, "--emulate", tmp.file("after"), "--speed", "0"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string said = "sinu fly: " + state + ": a warm start from the state saved 20.0 s before the first fix";
  const std::size_t first = r.err.find(said);
  EXPECT_NE(first, std::string::npos) << r.err.substr(0, 3000);  // in the health output when it happens
  EXPECT_NE(r.err.rfind(said), first) << "and again with the end line";
  EXPECT_NE(r.err.find("solution ok"), std::string::npos) << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
}

// An accelerometer read at the wrong full scale (configured +-16 g, decoded
// as +-2 g: 8x; the other way 1/8x) is every sample a valid number: the
// unit must not fly on it. The alignment is refused and both the health line
// and the end line say why.
TEST(FlyEmulate, AnAccelerometerAtTheWrongScaleIsRefusedAndSaidSo) {
  TempDir tmp;
  const FlyFlight fl = make_fly_flight(tmp, "flight", 300, 13);  // the simulator's shortest flight
  const std::string wrong = with_scaled_columns(fl.quantised, tmp.file("eighth"), {{"ax", 0.125}, {"ay", 0.125}, {"az", 0.125}});
  const std::string config = write_fly_config(tmp, "fly");
  const ProcessResult r = run_sinu({"fly", "--health-period", "0.001", "--config", config, "--emulate", wrong, "--speed", "0"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("NAV REFUSED: accelerometer reads 0.125x gravity"), std::string::npos) << r.err.substr(0, 2000);
  EXPECT_NE(r.err.find("0 solutions, NOT ALIGNED: the accelerometer reads 0.125x gravity"), std::string::npos)
      << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
}

// systemctl stop (SIGTERM) and Ctrl-C (SIGINT) mid-flight: the loop ends its
// turn, the navigation log and the recording are flushed whole, exit 0.
TEST(FlyEmulate, SigtermAndSigintFlushTheLogAndTheRecordingAndExitZero) {
  TempDir tmp;
  const FlyFlight fl = make_fly_flight(tmp, "flight", 300, 14);
  for (const int sig : {SIGTERM, SIGINT}) {
    const std::string name = sig == SIGTERM ? "term" : "int";
    const std::string config = write_fly_config(tmp, name), raw = tmp.file(name + ".raw");
    const ProcessResult r = run_sinu({"fly", "--config", config, "--emulate", fl.quantised, "--speed", "1",
                                      "--record", raw, "--health-period", "0"},
                                     8.0, sig);  // 8 s in: a few seconds after alignment on this flight
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    const std::string log = read_file(tmp.file(name + "_nav.csv"));
    ASSERT_FALSE(log.empty());
    EXPECT_EQ(log.back(), '\n') << "the last row whole";
    const CsvNumbers rows = read_csv_numbers(tmp.file(name + "_nav.csv"));
    ASSERT_GT(rows.rows.size(), 5u) << name << ": navigated before the signal";
    EXPECT_LT(rows.rows.back()[0], fl.t0_s + 12.0) << "stopped when asked";
    const ProcessResult inspect = run_sinu({"inspect", "recording", raw});
    EXPECT_EQ(inspect.exit_code, 0) << inspect.err;
    EXPECT_EQ(inspect.out.find("truncated"), std::string::npos) << "closed, not cut: " << inspect.out;
    // And the recording replays to the log it ended with.
    ASSERT_EQ(run_sinu({"replay", "--in", raw, "--out", tmp.file(name + "_replay"), "--quiet"}).exit_code, 0);
    EXPECT_EQ(log, read_file(tmp.file(name + "_replay") + "/nav.csv"));
  }
}

}  // namespace
}  // namespace sinu::test
