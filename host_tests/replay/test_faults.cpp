// The fault-injection suite: one simulated 15-minute flight, calibrated from a
// bench session of the same unit, replayed with the default options
// (`sinu replay --in F --calib C`), once clean and once per fault injected at
// a known time in cruise. For each fault: no crash, the flags in nav.csv and
// the counters in summary.json say what happened, and the horizontal error is
// back within twice its fault-free value within 30 s of the fault's end (for
// the GNSS outage: of GNSS returning). The table in docs/experiments.md is
// this test's output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "estimator/nav/nav_health.hpp"
#include "host_tests/support/dataset_faults.hpp"
#include "host_tests/support/nav_error.hpp"
#include "host_tests/support/read_json.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

namespace fs = std::filesystem;
namespace f = est::nav_flag;

constexpr double kFaultAt = 400.0;     // s after the first IMU sample: cruise, after the climb-out
constexpr double kRecovery = 30.0;     // s after the fault's end
constexpr double kScoreWindow = 60.0;  // the error is compared over [end + 30, end + 90] s

/// The first time after `from` from which the error stays within twice the
/// fault-free error (1 s means) for 10 s.
double recovered_at(const ErrorSeries& s, const ErrorSeries& clean, double from) {
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    if (s.t[i] < from) continue;
    bool ok = true;
    for (double u = s.t[i]; u < s.t[i] + 10.0 && ok; u += 1.0)
      ok = rms_between(s, u, u + 1.0) <= 2.0 * std::max(rms_between(clean, u, u + 1.0), 0.5);
    if (ok) return s.t[i];
  }
  return NAN;
}

class Faults : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    const std::string flight = file("flight"), bench = file("bench");
    ASSERT_EQ(run_sinu({"simulate", "flight", "--out", flight, "--seed", "31", "--duration", "900"}).exit_code, 0);
    ASSERT_EQ(run_sinu({"simulate", "static", "--out", bench, "--seed", "31", "--hours", "1"}).exit_code, 0);
    ASSERT_EQ(run_sinu({"calibrate", "--in", bench, "--out", file("calib.json"), "--quiet"}).exit_code, 0);
    t0_ = dataset_times(flight).imu.first_s;
    const auto r = run_sinu({"replay", "--in", flight, "--calib", file("calib.json"), "--quiet", "--out", file("clean")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    clean_ = new ErrorSeries(error_series(file("clean") + "/nav.csv", flight + "/truth.csv"));
  }
  static void TearDownTestSuite() {
    delete clean_;
    delete dir_;
  }
  static std::string file(const std::string& name) { return dir_->file(name); }

  struct Outcome {
    nlohmann::json summary;
    ErrorSeries series;
    std::string err;
  };
  /// Injects `faults` into a copy of the flight and replays it with the default options.
  Outcome replay_with(const std::string& name, const std::vector<Fault>& faults,
                      const std::vector<std::string>& extra_args = {}) {
    const std::string ds = file(name), out = file(name + "_out");
    inject_faults(file("flight"), ds, faults);
    std::vector<std::string> args{"replay", "--in", ds, "--calib", file("calib.json"), "--quiet", "--out", out};
    args.insert(args.end(), extra_args.begin(), extra_args.end());
    const auto r = run_sinu(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return {read_json(out + "/summary.json"), error_series(out + "/nav.csv", ds + "/truth.csv"), r.err};
  }
  /// The recovery criterion, and one table row for docs/experiments.md.
  void expect_recovered(const std::string& name, const Outcome& o, double fault_start, double fault_end) {
    const double from = fault_end + kRecovery, to = from + kScoreWindow;
    const double faulty = rms_between(o.series, from, to), free = rms_between(*clean_, from, to);
    // Twice the fault-free error, but not below 0.5 m: the clean error itself
    // is ~1 m (the receiver's correlated error), so 2x is well above noise.
    EXPECT_LE(faulty, 2.0 * std::max(free, 0.5)) << name;
    const double rec = recovered_at(o.series, *clean_, fault_end);
    std::printf("| %s | %.1f | %.2f | %.2f | %.1f | %s |\n", name.c_str(), max_between(o.series, fault_start, fault_end + 60.0),
                free, faulty, rec - fault_end, o.summary["health"]["status"].get<std::string>().c_str());
  }

  static inline TempDir* dir_ = nullptr;
  static inline ErrorSeries* clean_ = nullptr;
  static inline double t0_ = 0.0;
};

TEST_F(Faults, GnssPositionJumpOf100mForTenSecondsIsHeldOffNotFollowed) {
  const double start = t0_ + kFaultAt;
  const auto o = replay_with("jump", {GnssPositionJump{start, 10.0, {100.0, 0.0, 0.0}}});
  const std::uint32_t fl = flags_between(o.series, start, start + 12.0);
  EXPECT_TRUE(fl & f::kGnssPosRejected);
  EXPECT_TRUE(fl & f::kGnssSuspect) << "the receiver's velocity still agrees: the GNSS, not the filter, is wrong";
  EXPECT_EQ(o.summary["health"]["resets"]["position"], 0) << "a 10 s jump must not be followed";
  EXPECT_GE(o.summary["rejected"]["gnss_position"].get<int>(), 40);  // ~50 epochs in 10 s at 5 Hz
  EXPECT_LT(max_between(o.series, start, start + 12.0), 10.0) << "the solution stays where it was";
  expect_recovered("GNSS position +100 m for 10 s", o, start, start + 10.0);
}

TEST_F(Faults, FiveSecondsOfGarbageOnTheGnssStream) {
  const double start = t0_ + kFaultAt;
  const auto o = replay_with("garbage", {GnssGarbage{start, 5.0, 3}});
  EXPECT_GE(o.summary["corrupt_sentences"].get<int>(), 60);  // ~15 sentences/s for 5 s
  EXPECT_GE(o.summary["health"]["gnss_timeouts"].get<int>(), 1);
  EXPECT_TRUE(flags_between(o.series, start, start + 6.0) & f::kGnssTimeout);
  expect_recovered("5 s of garbage on the GNSS stream", o, start, start + 5.0);
}

TEST_F(Faults, A120SecondGnssOutageIsDeadReckonedAndRecovered) {
  const double start = t0_ + kFaultAt;
  const auto o = replay_with("outage", {GnssOutage{start, 120.0}});
  EXPECT_GE(o.summary["health"]["gnss_timeout_s"].get<double>(), 115.0);
  EXPECT_TRUE(flags_between(o.series, start + 5.0, start + 115.0) & f::kGnssTimeout);
  EXPECT_EQ(o.summary["health"]["status"], "ok") << "GNSS returning inside the filter's own sigma needs no reset";
  expect_recovered("120 s GNSS outage", o, start, start + 120.0);
}

TEST_F(Faults, OneSecondOfPeggedAccelerometer) {
  const double start = t0_ + kFaultAt;
  ImuClip clip{start, 1.0};
  clip.accel_full_scale_m_s2 = 4.0 * 9.80665;  // the simulated unit's range, which the replay is not told
  const auto o = replay_with("clip1", {clip});
  EXPECT_GE(o.summary["imu"]["clipped_samples"].get<int>(), 35);  // 40 samples in 1 s, the first two unseen
  EXPECT_TRUE(flags_between(o.series, start, start + 3.0) & f::kClipping);
  expect_recovered("1 s accelerometer pegged at +4 g", o, start, start + 1.0);
}

TEST_F(Faults, FiveSecondsOfClippedVibration) {
  const double start = t0_ + kFaultAt;
  ImuClip clip{start, 5.0};
  clip.accel_full_scale_m_s2 = 4.0 * 9.80665;
  clip.mode = ClipMode::Vibration;
  const auto o = replay_with("clip5", {clip});
  EXPECT_GE(o.summary["imu"]["clipped_samples"].get<int>(), 100);
  EXPECT_TRUE(flags_between(o.series, start, start + 6.0) & f::kClipping);
  expect_recovered("5 s of clipped vibration (3 x full scale)", o, start, start + 5.0);
}

TEST_F(Faults, AThreeSecondImuGapIsCountedAndBridged) {
  const double start = t0_ + kFaultAt;
  const auto o = replay_with("gap", {ImuGap{start, 3.0}});
  EXPECT_EQ(o.summary["imu"]["gaps"].get<int>(), 1);
  EXPECT_NEAR(o.summary["imu"]["longest_gap_s"].get<double>(), 3.0, 0.05);
  EXPECT_TRUE(flags_between(o.series, start, start + 4.0) & f::kImuGap);
  expect_recovered("3 s IMU gap", o, start, start + 3.0);
}

TEST_F(Faults, ARepeatedAndABackwardsTimeStampAreDroppedAndCounted) {
  const double start = t0_ + kFaultAt;
  const auto o = replay_with("time", {ImuTimeGlitch{start, TimeGlitchKind::Repeat},
                                      ImuTimeGlitch{start + 20.0, TimeGlitchKind::Backwards, 0.5}});
  EXPECT_EQ(o.summary["imu"]["time_anomalies"].get<int>(), 2);
  EXPECT_EQ(o.summary["imu"]["non_increasing"].get<int>(), 2);
  EXPECT_NE(o.summary["imu"]["first_anomaly"].get<std::string>().find("imu.csv:"), std::string::npos)
      << "file and line named";
  EXPECT_NE(o.err.find("dropped"), std::string::npos) << "said on stderr: " << o.err;
  EXPECT_TRUE(flags_between(o.series, start - 3.0, start + 2.0) & f::kImuDropped);
  expect_recovered("repeated and backwards IMU time stamp", o, start, start + 20.0);
}

TEST_F(Faults, NanFromTheDriverIsDroppedAndCounted) {
  const double start = t0_ + kFaultAt;
  const auto o = replay_with("nan", {ImuNonFinite{start, 0.5}});
  EXPECT_GE(o.summary["imu"]["invalid"].get<int>(), 19);  // 20 rows in 0.5 s at 40 Hz
  EXPECT_EQ(o.summary["imu"]["invalid"], o.summary["imu"]["non_finite_rows"]);
  EXPECT_TRUE(flags_between(o.series, start - 3.0, start + 2.0) & f::kImuDropped);
  expect_recovered("0.5 s of NaN from the IMU driver", o, start, start + 0.5);
}

// The accelerometer's bias along gravity shifts by 0.5 m/s^2 in cruise (50
// mg: a knock, or vibration that changes with the throttle; the calibrated
// model allows ~2 mg). No receiver here reports a vertical velocity, so only
// the heights see it: before the vertical check (estimator/nav/vertical_check.hpp)
// each fix pulled the height back while vd ran 10-15 m/s wrong for minutes
// with a claimed sigma of 0.2 m/s and every fix accepted (a 1 m/s^2 shift:
// vd RMSE 218 m/s, 2883 fixes rejected). Now vd is reset to the heights' rate
// within seconds and the bias is learnt again.
TEST_F(Faults, AnAccelerometerBiasShiftAlongGravityIsCaughtByTheHeights) {
  const double start = t0_ + kFaultAt;
  const auto o = replay_with("bias_shift", {ImuBiasShift{start, 3, 0.5}});
  EXPECT_EQ(o.summary["health"]["resets"]["vertical_velocity"].get<int>(), 1) << o.summary["health"].dump();
  EXPECT_TRUE(flags_between(o.series, start, start + 15.0) & f::kVelocityReset) << "caught within 15 s";
  // The vertical velocity 30 s on: back to the fault-free flight's (~0.1 m/s
  // RMS; 0.5 m/s is five times that and a thirtieth of the error before).
  EXPECT_LT(rms_of(o.series.t, o.series.err_vd_m_s, start + kRecovery, start + kRecovery + kScoreWindow), 0.5);
  expect_recovered("accelerometer z bias +0.5 m/s^2 (from then on)", o, start, start);
}

// The printed summary of a replay that had to reset: the reset before any
// figure, then where to look for why (the diagnose command for this data).
TEST_F(Faults, AResetIsPrintedBeforeAnyFigureWithTheDiagnoseCommand) {
  const std::string ds = file("reset_print");
  inject_faults(file("flight"), ds, {ImuBiasShift{t0_ + kFaultAt, 3, 0.5}});
  const auto r = run_sinu({"replay", "--in", ds, "--calib", file("calib.json"), "--out", ds + "_out"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::size_t reset = r.out.find("solution RESET to GNSS"), rmse = r.out.find("rmse:");
  ASSERT_NE(reset, std::string::npos) << r.out;
  EXPECT_LT(reset, rmse) << r.out;
  EXPECT_NE(r.out.find("why: sinu diagnose --in " + ds + " --calib " + file("calib.json")), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;
}

// The gyro's bias about the vertical shifts by 2 deg/s in cruise (a knock, a
// temperature step; the calibrated walk allows ~0.01 deg/s). The heading turns
// at that rate and the magnetometer's innovations grow on one side: before the
// heading check (estimator/nav/heading_check.hpp) the field's noise learner
// took them for noise (its sigma to the 5-uT ceiling) while the bias was learnt
// over five minutes: on seed 2001 the heading went 49 deg wrong under a
// claimed 0.2-6 deg, 6 resets from 12 minutes on, attitude RMSE 8.8 deg
// (0.25 fault-free). Now the bias about the vertical is widened within
// seconds and learnt in about a minute.
TEST_F(Faults, AGyroBiasShiftAboutTheVerticalIsCaughtByTheMagnetometer) {
  const double start = t0_ + kFaultAt;
  const double shift_rad_s = 2.0 * M_PI / 180.0;
  const auto o = replay_with("gyro_shift", {ImuBiasShift{start, 6, shift_rad_s}});
  EXPECT_GE(o.summary["health"]["gyro_bias_releases"].get<int>(), 1) << o.summary["health"].dump();
  EXPECT_TRUE(flags_between(o.series, start, start + 15.0) & f::kGyroBiasReleased) << "caught within 15 s";
  EXPECT_EQ(o.summary["health"]["status"].get<std::string>(), "ok") << "no reset needed";
  // The heading from 60 s after the shift for two minutes: within 1.5 deg
  // RMS (the fault-free flight's ~0.2 deg, the shift's own 120 deg a minute;
  // before the check 20-50 deg), and the bias learnt to 10 %.
  EXPECT_LT(rms_of(o.series.t, o.series.err_yaw_deg, start + 60.0, start + 180.0), 1.5);
  const double bias = nav_value(file("gyro_shift_out") + "/nav.csv", "gyro_bias_z", NavRow::Last);
  const double bias_clean = nav_value(file("clean") + "/nav.csv", "gyro_bias_z", NavRow::Last);
  EXPECT_NEAR(bias - bias_clean, shift_rad_s, 0.1 * shift_rad_s);
  expect_recovered("gyro z bias +2 deg/s (from then on)", o, start, start);
}

// The same shift without a magnetometer: in straight flight nothing but the
// gyro sees the heading (a yaw error leaves the velocity unchanged until the
// vehicle accelerates), so the first turn after it finds the heading some
// 70 deg off and resets it to the GNSS track. That reset now also lets the
// bias about the vertical move (a heading lost that far is a bias beyond its
// walk); before, the walk kept the bias for minutes and the next turns lost
// the heading again: on this flight yaw 14.4 deg RMS over 120-400 s after
// the shift, 18.2 deg attitude RMSE, 8 resets; now 4.9 deg, 12.0 deg, 6.
TEST_F(Faults, WithoutAMagnetometerAYawResetLetsAShiftedGyroBiasMove) {
  const double start = t0_ + kFaultAt;
  const double shift_rad_s = 2.0 * M_PI / 180.0;
  const auto o = replay_with("gyro_shift_no_mag", {ImuBiasShift{start, 6, shift_rad_s}}, {"--no-mag"});
  const auto& health = o.summary["health"];
  EXPECT_GE(health["resets"]["yaw"].get<int>(), 1) << health.dump();
  EXPECT_GE(health["gyro_bias_releases"].get<int>(), health["resets"]["yaw"].get<int>()) << health.dump();
  // Between the two figures above (14.4 before, 4.9 now): the heading is
  // held once the bias has moved, not lost again turn after turn.
  EXPECT_LT(rms_of(o.series.t, o.series.err_yaw_deg, start + 120.0, start + 400.0), 9.0);
  const double bias = nav_value(file("gyro_shift_no_mag_out") + "/nav.csv", "gyro_bias_z", NavRow::Last);
  const double bias_clean = nav_value(file("clean") + "/nav.csv", "gyro_bias_z", NavRow::Last);
  EXPECT_NEAR(bias - bias_clean, shift_rad_s, 0.1 * shift_rad_s);
}

// What `sinu diagnose` makes of a bias that moved: no effect of the
// vocabulary is a step, so it named whatever fitted some of it (on seed 2001
// a 2-deg/s z gyro step was gyro_temp_bias and mag_soft_iron, a 0.3-m/s^2 x
// accelerometer step gyro_misalign and mag_soft_iron). Now it replays the
// baseline with each bias's walk scaled up and names the moved bias instead
// when that fits better than any effect (diagnose_runner.cpp, test_bias_walks).
struct MovedBias {
  const char* name;
  std::size_t column;
  double delta;
  const char* sensor;
};
class DiagnoseMovedBias : public Faults, public ::testing::WithParamInterface<MovedBias> {};

TEST_P(DiagnoseMovedBias, IsNamedAsAMovedBiasNotAsAnEffectAndTheErrorFalls) {
  const MovedBias c = GetParam();
  const std::string ds = file(std::string("moved_") + c.name), out = ds + "_diag";
  inject_faults(file("flight"), ds, {ImuBiasShift{t0_ + kFaultAt, c.column, c.delta}});
  const auto r = run_sinu({"diagnose", "--in", ds, "--calib", file("calib.json"), "--quiet", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto d = read_json(out + "/diagnosis.json");
  ASSERT_TRUE(d.contains("bias_walk")) << d.dump(1);
  EXPECT_TRUE(d["bias_walk"]["named"].get<bool>()) << d["bias_walk"].dump();
  EXPECT_EQ(d["bias_walk"]["sensor"], c.sensor) << d["bias_walk"].dump();
  EXPECT_EQ(d["missing_effects"].size(), 0u) << d["missing_effects"].dump();
  EXPECT_NE(r.out.find("bias moved: the "), std::string::npos) << r.out;
  // Followed with the wider walk the attitude error falls (measured below).
  const double before = d["before"]["rmse_att_deg"].get<double>(), after = d["after"]["rmse_att_deg"].get<double>();
  std::printf("%s: walk %gx, gain %.1f (threshold %.1f); attitude %.3f -> %.3f deg\n", c.name,
              d["bias_walk"]["scale"].get<double>(), d["bias_walk"]["nll_gain"].get<double>(),
              d["bias_walk"]["threshold"].get<double>(), before, after);
  EXPECT_LT(after, 0.8 * before);
}

// 1 deg/s about z and 0.5 m/s^2 along x: within what an ICM-20948 may shift
// over its temperature range or after a knock. Measured gains: gyro 799 (30x),
// accelerometer 10x 285 at 0.3 m/s^2, more at 0.5; the fault-free flight -8.7,
// threshold 225 for these 15 minutes.
INSTANTIATE_TEST_SUITE_P(Steps, DiagnoseMovedBias,
                         ::testing::Values(MovedBias{"gyro_z", 6, 1.0 * M_PI / 180.0, "gyro"},
                                           MovedBias{"accel_x", 1, 0.5, "accel"}),
                         [](const auto& p) { return std::string(p.param.name); });

// A moved bias and a missing effect in one flight: the moved bias takes the
// first round and the effect is found in the next, from the widened walk (the
// same seed with a lever arm: the same trajectory, noise and unit).
TEST_F(Faults, DiagnoseFindsAMovedBiasAndThenTheMissingEffect) {
  const std::string lever = file("lever"), ds = file("lever_moved"), out = ds + "_diag";
  std::ofstream(file("lever.json")) << R"({"lever_arm": [0.6, -0.4, -0.5]})";
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", lever, "--seed", "31", "--duration", "900", "--effects",
                      file("lever.json")})
                .exit_code,
            0);
  inject_faults(lever, ds, {ImuBiasShift{t0_ + kFaultAt, 6, 1.0 * M_PI / 180.0}});
  const auto r = run_sinu({"diagnose", "--in", ds, "--calib", file("calib.json"), "--quiet", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto d = read_json(out + "/diagnosis.json");
  EXPECT_TRUE(d["bias_walk"]["named"].get<bool>()) << d["bias_walk"].dump();
  ASSERT_EQ(d["missing_effects"].size(), 1u) << d["missing_effects"].dump();
  EXPECT_EQ(d["missing_effects"][0], "lever_arm");
}

// The fault-free flight: its calibrated walks fit, nothing moved.
TEST_F(Faults, DiagnoseFindsNoMovedBiasInTheFaultFreeFlight) {
  const std::string out = file("clean_diag");
  const auto r = run_sinu({"diagnose", "--in", file("flight"), "--calib", file("calib.json"), "--quiet", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto d = read_json(out + "/diagnosis.json");
  std::printf("fault-free: best walk %s %gx, gain %.1f (threshold %.1f)\n",
              d["bias_walk"]["sensor"].get<std::string>().c_str(), d["bias_walk"]["scale"].get<double>(),
              d["bias_walk"]["nll_gain"].get<double>(), d["bias_walk"]["threshold"].get<double>());
  EXPECT_FALSE(d["bias_walk"]["named"].get<bool>()) << d["bias_walk"].dump();
  EXPECT_EQ(r.out.find("bias moved"), std::string::npos) << r.out;
}

// A fault-free flight never trips the vertical check nor the heading check.
TEST_F(Faults, TheFaultFreeFlightNeedsNoVerticalResetNorGyroBiasRelease) {
  const auto s = read_json(file("clean") + "/summary.json");
  EXPECT_EQ(s["health"]["resets"]["vertical_velocity"].get<int>(), 0);
  EXPECT_EQ(s["health"]["gyro_bias_releases"].get<int>(), 0);
}

// A soft iron the default model lacks is no gyro shift. The diagnose
// evaluation's seed-1012 flight (a 14 % soft iron) misfits the field by a few
// degrees of heading that follow the heading, one-signed through each turn:
// judged in turns too, the heading check fired 8 times and the attitude went
// 1.59 -> 2.20 deg. On straight legs only it never fires and the replay is
// the one without the check.
TEST(HeadingCheckFlights, ASoftIronTheModelLacksIsNoGyroShift) {
  TempDir dir;
  const std::string flight = dir.file("flight"), bench = dir.file("bench"), calib = dir.file("calib.json");
  // That flight's draw, given explicitly (the draws change whenever the vocabulary grows).
  const std::string effects = dir.write("effects.json", R"({"mag_soft_iron": [[1.102572817683074, 0.003726901861522941,
      -0.06623477750547523], [0.003726901861522941, 0.8631930510052679, -0.059422793366868676],
      [-0.06623477750547523, -0.059422793366868676, 0.8880214318118911]]})");
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", flight, "--seed", "1012", "--duration", "1200", "--effects",
                      effects})
                .exit_code,
            0);
  ASSERT_EQ(run_sinu({"simulate", "static", "--out", bench, "--seed", "1012", "--hours", "1"}).exit_code, 0);
  ASSERT_EQ(run_sinu({"calibrate", "--in", bench, "--out", calib, "--quiet"}).exit_code, 0);
  const auto r = run_sinu({"replay", "--in", flight, "--calib", calib, "--quiet", "--out", dir.file("out")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto s = read_json(dir.file("out") + "/summary.json");
  EXPECT_EQ(s["health"]["gyro_bias_releases"].get<int>(), 0) << s["health"].dump();
  // 1.59 deg without the check, 2.20 with it judged in turns; 1.8 between.
  EXPECT_LT(s["rmse"]["att_deg"].get<double>(), 1.8);
}

}  // namespace
}  // namespace sinu::test
