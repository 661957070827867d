// The real logs in ../shared/data/real/, replayed as a newcomer would: the
// dataset and nothing else (`sinu replay --in LOG --out DIR`). Skipped with a
// message where ../shared/ is absent. The tables in docs/experiments.md are
// this test's output.
//  - drive_0708, a car with a consumer IMU and an RTK receiver: the default
//    must find out it is a car (it is never told) and dead-reckon the issue's
//    ten 15-s outages (every 45 s from 60 s after the car first exceeds
//    3 m/s) to at most 8 m RMS: half of what a public 21-state GNSS/INS
//    reaches on the same outages (15.8 m); at half the IMU rate the same.
//  - the same drive with its unit mounted turned 90 deg: aligned on the GNSS
//    course, the solution is turned to the unit's heading once the in-motion
//    alignment sees it, and the car is recognised with its lateral axis along
//    body x.
//  - uav_log171, a real quadcopter: the magnetometer fused from its first
//    field sample (the first imu.csv row has none), no reset, no loss, and
//    the horizontal error against the autopilot's own EKF (a peer fusing the
//    same sensors, not ground truth) under 0.6 m.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "host_tests/support/dataset_faults.hpp"
#include "host_tests/support/faults/text_lines.hpp"
#include "host_tests/support/nav_error.hpp"
#include "host_tests/support/read_json.hpp"
#include "host_tests/support/replay_helpers.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/shared_data.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

/// The first truth.csv time with a horizontal speed above `speed_m_s`.
double first_moving_s(const std::string& truth_csv, double speed_m_s) {
  std::ifstream in(truth_csv);
  std::string line;
  std::getline(in, line);  // header t,lat,lon,h,vn,ve,vd,...
  while (std::getline(in, line)) {
    double v[7] = {};
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6]) == 7 &&
        std::hypot(v[4], v[5]) > speed_m_s)
      return v[0];
  }
  return NAN;
}

TEST(RealLogs, TheDriveIsFoundToBeACarAndItsTenOutagesDriftUnderEightMetres) {
  SINU_REQUIRE_SHARED(drive, "data/real/drive_0708");
  const double moving = first_moving_s(drive + "/truth.csv", 3.0);
  ASSERT_TRUE(std::isfinite(moving));
  const std::string outages = outage_schedule(moving + 60.0);
  TempDir dir;
  const auto r = run_sinu({"replay", "--in", drive, "--outage", outages, "--out", dir.file("out")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto s = read_json(dir.file("out") + "/summary.json");
  EXPECT_EQ(s["health"]["status"], "ok");
  EXPECT_EQ(s["vehicle"]["configured"], "auto");
  ASSERT_EQ(s["vehicle"]["detected"], "ground") << "the default must find out it is a car";
  // Within the first outage's minute of lead-in: 20 s of driving and a turn is the evidence it needs.
  EXPECT_LT(s["vehicle"]["detected_at_s"].get<double>(), moving + 60.0);
  double sum2 = 0.0;
  for (const auto& o : s["outages"]) {
    ASSERT_FALSE(o["max_drift_h_m"].is_null()) << "outage at " << o["start"] << " not scored";
    const double d = o["max_drift_h_m"].get<double>();
    std::printf("| %.1f | %.1f |\n", o["start"].get<double>(), d);
    sum2 += d * d;
  }
  const double rms = std::sqrt(sum2 / 10.0);
  std::printf("drift RMS over the ten outages: %.2f m (target 8 m; a public 21-state GNSS/INS: 15.8 m)\n", rms);
  EXPECT_LE(rms, 8.0);
  // Its truth.csv is the RTK solution that feeds gps.nmea: the RMSE outside
  // the outages is the distance from its own fixes, and the replay says so
  // (the fixes re-timed by the learnt latency, 7 ms, had hidden it: 0.065 m).
  EXPECT_TRUE(s["gnss_only_rmse"]["truth_is_gnss_input"].get<bool>());
  EXPECT_LT(s["gnss_only_rmse"]["pos_h_m"].get<double>(), 0.01);
  EXPECT_NE(r.out.find("truth.csv is the GNSS input itself"), std::string::npos) << r.out;
}

// The loop on the car, as a user runs it: diagnose finds that the receiver's
// velocity lags its position by half its 4-Hz period (0.128 s measured) and,
// once it has that, that the fixes are valid after they arrive on the IMU's
// clock (the learnt latency below zero: the IMU's stamps are late, 0.111 s
// measured, against the dataset's notes' 0.01-0.045 s from the lagging
// velocity); --apply writes both, and the next replay from the model file
// sits 0.08 m from the RTK fixes (0.71 m before) and drifts 1.80 m over the
// ten outages (2.66 m before). Bounds: the named effects, the IMU latency
// within 0.05 s of a half-period-plus-receiver figure nobody measured
// independently (it is what the data say; 0.06-0.16 s), and a lower drift.
TEST(RealLogs, OnTheDriveDiagnoseFindsTheLateVelocityAndTheLateImuAndTheDriftFalls) {
  SINU_REQUIRE_SHARED(drive, "data/real/drive_0708");
  TempDir dir;
  const auto d = run_sinu({"diagnose", "--in", drive, "--rounds", "5", "--apply", "--quiet", "--out", dir.file("diag")});
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const auto j = read_json(dir.file("diag") + "/diagnosis.json");
  ASSERT_GE(j["missing_effects"].size(), 1u) << j.dump(1);
  EXPECT_EQ(j["missing_effects"][0], "gps_velocity_latency");
  const auto model = read_json(dir.file("diag") + "/model.json");
  ASSERT_TRUE(model.contains("imu_latency_s")) << model.dump(1);
  EXPECT_NEAR(model["imu_latency_s"].get<double>(), 0.11, 0.05);
  EXPECT_NEAR(model["effects"]["gps_velocity_latency"]["estimate"][0].get<double>(), 0.125, 0.02);
  const std::string outages = drive_0708_outages();
  const auto before = run_sinu({"replay", "--in", drive, "--outage", outages, "--quiet", "--out", dir.file("before")});
  const auto after = run_sinu({"replay", "--in", drive, "--outage", outages, "--model-file", dir.file("diag") + "/model.json",
                               "--quiet", "--out", dir.file("after")});
  ASSERT_EQ(before.exit_code, 0) << before.err;
  ASSERT_EQ(after.exit_code, 0) << after.err;
  const auto sb = read_json(dir.file("before") + "/summary.json"), sa = read_json(dir.file("after") + "/summary.json");
  std::printf("ten outages: %.3f -> %.3f m\n", sb["outage_max_drift_h_rms_m"].get<double>(),
              sa["outage_max_drift_h_rms_m"].get<double>());
  EXPECT_LT(sa["outage_max_drift_h_rms_m"].get<double>(), sb["outage_max_drift_h_rms_m"].get<double>());
}

/// imu.csv at half its rate, as a unit set to half the output data rate
/// writes it: each pair of rows averaged (a boxcar filter, the sensor's own
/// decimation) and stamped at the pair's midpoint; empty fields stay empty.
void write_half_rate_imu(const std::string& from, const std::string& to) {
  std::ifstream in(from);
  std::ofstream out(to);
  std::string header, a, b;
  std::getline(in, header);
  out << header << '\n';
  while (std::getline(in, a) && std::getline(in, b)) {
    const auto fa = faults::split_fields(a), fb = faults::split_fields(b);
    ASSERT_EQ(fa.size(), fb.size()) << a << " / " << b;
    for (std::size_t i = 0; i < fa.size(); ++i) {
      if (i > 0) out << ',';
      if (fa[i].empty() || fb[i].empty()) continue;
      char mean[32];
      std::snprintf(mean, sizeof mean, "%.8f", 0.5 * (std::stod(fa[i]) + std::stod(fb[i])));  // the inputs' digits
      out << mean;
    }
    out << '\n';
  }
}

/// The drive as it is and a copy whose imu.csv `write_imu(from, to)` writes,
/// both replayed over the ten outages: their summaries (outputs in
/// dir/as_is and dir/altered).
struct DrivePair {
  nlohmann::json as_is, altered;
};
void replay_drive_and_altered(const std::string& drive, const TempDir& dir,
                              void (*write_imu)(const std::string&, const std::string&), DrivePair& out) {
  const std::string copy = dir.file("altered_dataset");
  copy_dataset_except(drive, copy, "imu.csv");
  ASSERT_NO_FATAL_FAILURE(write_imu(drive + "/imu.csv", copy + "/imu.csv"));
  const std::string outages = drive_0708_outages();
  out.as_is = replay_summary({"replay", "--in", drive, "--outage", outages, "--quiet", "--out", dir.file("as_is")});
  out.altered = replay_summary({"replay", "--in", copy, "--outage", outages, "--quiet", "--out", dir.file("altered")});
}

// The tuning is in physical units, not per sample: the same car at 50 Hz
// (its 100-Hz samples averaged in pairs) must dead-reckon the ten outages as
// at 100 Hz. Measured 2.490 against 2.558 m; 15 % allows the first outages'
// few-sample differences in when the filter aligns and learns. (Dropping every
// other sample instead aliases the engine's vibration: 6.3 m, the sensor's
// physics, not the filter's.)
TEST(RealLogs, TheDriveAtHalfItsImuRateDriftsAsAtTheFullRate) {
  SINU_REQUIRE_SHARED(drive, "data/real/drive_0708");
  TempDir dir;
  DrivePair p;
  ASSERT_NO_FATAL_FAILURE(replay_drive_and_altered(drive, dir, write_half_rate_imu, p));
  const nlohmann::json &sf = p.as_is, &sh = p.altered;
  EXPECT_EQ(sh["health"]["status"], "ok");
  const double d_full = sf["outage_max_drift_h_rms_m"].get<double>(), d_half = sh["outage_max_drift_h_rms_m"].get<double>();
  std::printf("ten outages: 100 Hz %.3f m, 50 Hz %.3f m\n", d_full, d_half);
  EXPECT_NEAR(d_half, d_full, 0.15 * d_full);
}

/// imu.csv of a unit sitting on the car turned by roll, pitch, yaw (ZYX,
/// the unit w.r.t. the car's axes, the drive's own mounting taken as the
/// car's): each vector v becomes C_vb^T v; empty fields stay empty.
void write_imu_on_bracket(const std::string& from, const std::string& to, double roll_deg, double pitch_deg,
                          double yaw_deg) {
  constexpr double kDeg = 3.14159265358979323846 / 180.0;
  const Eigen::Matrix3d C_bv = (Eigen::AngleAxisd(yaw_deg * kDeg, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(pitch_deg * kDeg, Eigen::Vector3d::UnitY()) *
                                Eigen::AngleAxisd(roll_deg * kDeg, Eigen::Vector3d::UnitX()))
                                   .toRotationMatrix()
                                   .transpose();
  std::ifstream in(from);
  std::ofstream out(to);
  std::string line;
  std::getline(in, line);
  out << line << '\n';
  const auto header = faults::split_fields(line);
  const auto col = [&](const char* name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  while (std::getline(in, line)) {
    auto f = faults::split_fields(line);
    ASSERT_EQ(f.size(), header.size()) << line;
    for (const auto& xyz : {std::array{"ax", "ay", "az"}, std::array{"gx", "gy", "gz"}, std::array{"mx", "my", "mz"}}) {
      const std::size_t c[3] = {col(xyz[0]), col(xyz[1]), col(xyz[2])};
      if (c[0] >= f.size() || f[c[0]].empty() || f[c[1]].empty() || f[c[2]].empty()) continue;
      const Eigen::Vector3d v = C_bv * Eigen::Vector3d(std::stod(f[c[0]]), std::stod(f[c[1]]), std::stod(f[c[2]]));
      for (int k = 0; k < 3; ++k) {
        char text[32];
        std::snprintf(text, sizeof text, "%.9g", v(k));
        f[c[k]] = text;
      }
    }
    out << faults::join_fields(f) << '\n';
  }
}
void write_imu_turned_90(const std::string& from, const std::string& to) { write_imu_on_bracket(from, to, 0, 0, 90); }
void write_imu_turned_45(const std::string& from, const std::string& to) { write_imu_on_bracket(from, to, 0, 0, 45); }
void write_imu_turned_10(const std::string& from, const std::string& to) { write_imu_on_bracket(from, to, 0, 0, 10); }
void write_imu_pitched_10(const std::string& from, const std::string& to) { write_imu_on_bracket(from, to, 0, 10, 0); }

// Without a magnetometer the heading at the start is the GNSS course, which
// is the heading only if the unit's x axis points along the track. Turned 90
// deg on its mount, the drive was aligned 90 deg off and sure of it (sigma
// 8.6 deg), and no car was recognised (the car's motion along body y):
// 37.7 m over the ten outages, 111 m on the first. Now the in-motion
// alignment checks the course after the alignment and the solution is
// turned 7 s later (83 deg, the rest the filter had found itself), and the
// vehicle detector finds the car with the unit turned 90 deg on it (40 s
// after the start, as the drive as it is). Measured: its yaw then follows
// the as-is replay's 89.81 deg apart (median), 3.63 m over the ten outages
// (as it is 2.56 m; session 27, with the car's lateral axis taken as exactly
// body x, 90.01 deg and 3.36 m). Bounds: the median within 3 deg of the
// mounting, the drift within twice the as-is drift (the first outages come
// 50 s after the turn, the heading still settling: 4.9 and 4.2 m there).
TEST(RealLogs, TheDriveWithItsUnitMountedTurnedIsTurnedToTheUnitsHeading) {
  SINU_REQUIRE_SHARED(drive, "data/real/drive_0708");
  TempDir dir;
  DrivePair p;
  ASSERT_NO_FATAL_FAILURE(replay_drive_and_altered(drive, dir, write_imu_turned_90, p));
  const nlohmann::json &sa = p.as_is, &st = p.altered;
  EXPECT_TRUE(sa["alignment"]["course_turned_deg"].is_null()) << "the unit as mounted: the course is its heading";
  ASSERT_FALSE(st["alignment"]["course_turned_deg"].is_null()) << st["alignment"].dump();
  // The yaw of the turned replay against the as-is one's, from 5 s after the turn.
  const ErrorSeries e = error_series(dir.file("altered") + "/nav.csv", dir.file("as_is") + "/nav.csv");
  std::vector<double> apart;
  for (std::size_t i = 0; i < e.t.size(); ++i)
    if (e.t[i] > st["alignment"]["course_turned_at_s"].get<double>() + 5.0 && std::isfinite(e.err_yaw_deg[i]))
      apart.push_back(e.err_yaw_deg[i]);
  ASSERT_GT(apart.size(), 1000u);
  std::nth_element(apart.begin(), apart.begin() + std::ssize(apart) / 2, apart.end());
  const double median = apart[apart.size() / 2], drift = st["outage_max_drift_h_rms_m"].get<double>();
  std::printf("turned 90 deg: turned %.1f deg at %.1f s, then %.2f deg from the as-is heading (median); ten outages %.2f m\n",
              st["alignment"]["course_turned_deg"].get<double>(), st["alignment"]["course_turned_at_s"].get<double>(),
              median, drift);
  EXPECT_NEAR(median, 90.0, 3.0);
  EXPECT_EQ(st["vehicle"]["unit_on_vehicle"]["found"], true);
  EXPECT_NEAR(std::abs(st["vehicle"]["unit_on_vehicle"]["yaw_deg"].get<double>()), 90.0, 3.0);
  EXPECT_LT(drift, 2.0 * sa["outage_max_drift_h_rms_m"].get<double>());
}

// A unit on a bracket that is not square to the car (turned 45 deg) or
// tilted (pitched 10 deg nose up): before session 28 the vehicle detector
// knew only body y or x as the car's lateral axis and z as its vertical, found
// no car, and the drive dead-reckoned as an aircraft: 10.2 and 10.5 m over
// the ten outages (as it is 2.56 m). Now the car's axes are found in the
// body frame (the body velocity's principal axis, gravity's mean direction;
// a car does not bank into its turns) and the constraint acts along them.
// Measured: found at 47.3 deg (the heading's error then) and 10.3 deg;
// 2.95 and 2.43 m. Bounds: the angle within 3 deg (the heading's sigma when
// found, 5 deg, is what the yaw carries), the drift within 1.5 times the
// as-is drift (without the constraint it is four times).
TEST(RealLogs, TheDriveWithItsUnitOnABracketFindsTheCarsAxes) {
  SINU_REQUIRE_SHARED(drive, "data/real/drive_0708");
  struct Case {
    void (*write_imu)(const std::string&, const std::string&);
    const char* angle;
    double degrees;
  };
  for (const Case c : {Case{write_imu_turned_45, "yaw_deg", 45.0}, Case{write_imu_turned_10, "yaw_deg", 10.0},
                       Case{write_imu_pitched_10, "pitch_deg", 10.0}}) {
    SCOPED_TRACE(c.angle);
    TempDir dir;
    DrivePair p;
    ASSERT_NO_FATAL_FAILURE(replay_drive_and_altered(drive, dir, c.write_imu, p));
    const nlohmann::json& unit = p.altered["vehicle"]["unit_on_vehicle"];
    const double drift = p.altered["outage_max_drift_h_rms_m"].get<double>(),
                 as_is = p.as_is["outage_max_drift_h_rms_m"].get<double>();
    std::printf("%s %.0f: found %s, ten outages %.2f m (as it is %.2f m)\n", c.angle, c.degrees, unit.dump().c_str(),
                drift, as_is);
    EXPECT_EQ(p.altered["health"]["status"], "ok");
    ASSERT_EQ(unit["found"], true) << p.altered["vehicle"].dump();
    EXPECT_NEAR(unit[c.angle].get<double>(), c.degrees, 3.0);
    EXPECT_LT(drift, 1.5 * as_is);
  }
}

TEST(RealLogs, TheQuadcopterFusesItsMagnetometerAndStaysWithItsAutopilot) {
  SINU_REQUIRE_SHARED(uav, "data/real/uav_log171");
  TempDir dir;
  const auto r = run_sinu({"replay", "--in", uav, "--out", dir.file("out")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto s = read_json(dir.file("out") + "/summary.json");
  EXPECT_EQ(s["health"]["status"], "ok");
  EXPECT_EQ(s["health"]["resets"]["position"], 0);
  EXPECT_EQ(s["vehicle"]["detected"], nullptr) << "a quadcopter is no car";
  // 2143 field samples at 10 Hz, fused at most every 0.1 s from the first fix (45 s) on:
  // ~1900 chances; more than 1000 accepted says it is fused, not ignored.
  EXPECT_GT(s["accepted"]["magnetometer"].get<int>(), 1000);
  EXPECT_EQ(s["gnss"]["late"], 0) << "every fix fused or tested";
  const double pos_h = s["rmse"]["pos_h_m"].get<double>(), att = s["rmse"]["att_deg"].get<double>();
  std::printf("uav_log171 against the autopilot's EKF: horizontal %.3f m (GNSS alone %.3f), attitude %.2f deg\n",
              pos_h, s["gnss_only_rmse"]["pos_h_m"].get<double>(), att);
  EXPECT_LT(pos_h, 0.6);  // the target
  // Its u-blox holds the course below ~1.5 m/s (the same course to the digit
  // while the speed changes): 142 epochs, fused as zero within their speed.
  // Fused as velocities they had the solution 0.425 m from the peer, farther
  // than the fixes alone (0.411); now 0.358 (the fixes 0.404).
  EXPECT_GT(s["gnss"]["course_held"].get<int>(), 100);
  EXPECT_LT(pos_h, s["gnss_only_rmse"]["pos_h_m"].get<double>());
}

// The real quadcopter with a fault at 131.5 s, in its 302-deg spin: a 3-s
// IMU gap, or 30 s without GNSS. Its u-blox states 0.7-7 m (4.6x its error:
// docs/diagnose.md), so the filter's receiver-error state may move metres:
// before session 34 it took 2 m of the gap's drift from one fix (and 1.5 m
// of the outage's) and held the solution 3.9 m (1.2 m) from the peer for
// minutes, 15x (5x) the fault-free error. The bound: back within 2x
// the fault-free error within 30 s of the fault's end.
TEST(RealLogs, TheQuadcopterIsBackWithItsAutopilotWithinThirtySecondsOfAFault) {
  SINU_REQUIRE_SHARED(uav, "data/real/uav_log171");
  TempDir dir;
  ASSERT_EQ(run_sinu({"replay", "--in", uav, "--quiet", "--out", dir.file("clean")}).exit_code, 0);
  const ErrorSeries clean = error_series(dir.file("clean") + "/nav.csv", uav + "/truth.csv");
  const double t_fault = 131.5;
  const std::vector<std::pair<std::string, Fault>> faults = {{"imu_gap_3s", ImuGap{t_fault, 3.0}},
                                                             {"gnss_outage_30s", GnssOutage{t_fault, 30.0}}};
  for (const auto& [name, fault] : faults) {
    const double end = t_fault + (name == "imu_gap_3s" ? 3.0 : 30.0);
    inject_faults(uav, dir.file(name), {fault});
    const ProcessResult r = run_sinu({"replay", "--in", dir.file(name), "--quiet", "--out", dir.file(name + "_out")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const ErrorSeries e = error_series(dir.file(name + "_out") + "/nav.csv", dir.file(name) + "/truth.csv");
    // From 30 s after the fault's end, for a minute.
    const double after = rms_between(e, end + 30.0, end + 90.0), as_clean = rms_between(clean, end + 30.0, end + 90.0);
    const auto s = read_json(dir.file(name + "_out") + "/summary.json");
    std::printf("uav_log171, %s at %.1f s: %.3f m from the peer 30-90 s after it, %.3f m without it; %d hold(s)\n",
                name.c_str(), t_fault, after, as_clean, s["health"]["gnss_bias_holds"].get<int>());
    EXPECT_LT(after, 2.0 * as_clean) << name;
    EXPECT_GE(s["health"]["gnss_bias_holds"].get<int>(), 1) << name << ": the fault is a disturbance";
  }
}

}  // namespace
}  // namespace sinu::test
