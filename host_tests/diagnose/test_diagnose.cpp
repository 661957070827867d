// sinu diagnose on simulated flights with a hidden effect (the simulator's
// effect vocabulary): it must name the effect that is in the data, estimate
// it, and the error must fall when it is added; on a flight without an effect
// it must name nothing.
#include <gtest/gtest.h>

#include <cstdio>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "host_tests/support/dataset_faults.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/shared_data.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

nlohmann::json diagnose(const TempDir& dir, const std::string& effects_json, const std::vector<std::string>& extra = {}) {
  const std::string ds = (dir.path() / "flight").string(), out = (dir.path() / "diag").string();
  std::vector<std::string> sim = {"simulate", "flight", "--out", ds, "--seed", "9", "--duration", "600"};
  if (!effects_json.empty()) {
    const std::string path = (dir.path() / "effects.json").string();
    std::ofstream(path) << effects_json;
    sim.insert(sim.end(), {"--effects", path});
  }
  EXPECT_EQ(run_sinu(sim).exit_code, 0);
  // One round keeps the test short; the simulator's base GPS latency (45 ms) is known.
  std::vector<std::string> args = {"diagnose", "--in", ds, "--gps-latency", "0.045", "--rounds", "1", "--out", out};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = run_sinu(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("report: "), std::string::npos) << r.out;
  std::ifstream in(out + "/diagnosis.json");
  return nlohmann::json::parse(in);
}

const nlohmann::json& first_candidate(const nlohmann::json& d) { return d["rounds"][0]["candidates"][0]; }

/// Each of a candidate's estimates within 3 of its sigmas of the truth, or
/// within `floor` where that is wider (a sigma a long flight makes tiny).
void expect_within_3_sigma(const nlohmann::json& c, std::initializer_list<double> truth, double floor = 0.0) {
  std::size_t i = 0;
  for (const double t : truth) {
    const double tol = std::max(3.0 * c["sigma"][i].get<double>(), floor);
    EXPECT_NEAR(c["estimate"][i].get<double>(), t, tol) << "component " << i << ": " << c.dump();
    ++i;
  }
}

/// The dataset's first imu.csv time.
double first_t(const std::string& ds) {
  std::ifstream in(ds + "/imu.csv");
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  return std::stod(line);
}

/// A flight with one effect the model carries: nothing missing, one carried
/// finding (returned) of `effect`, and model.json (--apply) holding it (`model`).
nlohmann::json only_carried_finding(const TempDir& dir, const std::string& effects_json, const char* effect,
                                    nlohmann::json& model) {
  const auto d = diagnose(dir, effects_json, {"--apply"});
  EXPECT_EQ(d["missing_effects"].size(), 0u) << d.dump(1);
  std::ifstream m((dir.path() / "diag" / "model.json").string());
  model = nlohmann::json::parse(m);
  EXPECT_TRUE(model["effects"].contains(effect)) << model.dump(1);
  if (d["carried_findings"].size() != 1u || d["carried_findings"][0]["effect"] != effect) {
    ADD_FAILURE() << "expected one carried finding, " << effect << ": " << d.dump(1);
    return nullptr;
  }
  return d["carried_findings"][0];
}

// gps_latency is one of the default states, from the configured value: the
// baseline follows a hidden latency, so nothing is missing, but the
// configuration is wrong, and a user must learn it: named as carried and far
// from the configured value, and --apply writes it so the next flight starts from it.
TEST(Diagnose, TheDefaultModelFollowsAHiddenGpsLatencyAndTellsTheUser) {
  TempDir dir;
  nlohmann::json model;
  const auto f = only_carried_finding(dir, R"({"gps_latency": 0.2})", "gps_latency", model);
  ASSERT_FALSE(f.is_null());
  EXPECT_DOUBLE_EQ(f["assumed"][0].get<double>(), 0.045);
  // 0.045 s base + 0.2 s hidden; sigma ~0.005 s: 0.02 s is 4 sigma.
  EXPECT_NEAR(f["estimate"][0].get<double>(), 0.245, 0.02);
  EXPECT_DOUBLE_EQ(model["effects"]["gps_latency"]["estimate"][0].get<double>(), f["estimate"][0].get<double>());
  // Held to the 25 ms it is reported at (the next flight's state still follows a changed receiver).
  EXPECT_DOUBLE_EQ(model["effects"]["gps_latency"]["sigma"][0].get<double>(), 0.025);
  // The next diagnosis starts from the model file: the latency is known, no finding, and --apply keeps it.
  const std::string again = (dir.path() / "again").string();
  const auto r = run_sinu({"diagnose", "--in", (dir.path() / "flight").string(), "--gps-latency", "0.045", "--rounds",
                           "1", "--model-file", (dir.path() / "diag" / "model.json").string(), "--apply", "--quiet",
                           "--out", again});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream d2(again + "/diagnosis.json"), m2(again + "/model.json");
  EXPECT_EQ(nlohmann::json::parse(d2)["carried_findings"].size(), 0u);
  const auto model2 = nlohmann::json::parse(m2);
  ASSERT_TRUE(model2["effects"].contains("gps_latency")) << model2.dump(1);
  EXPECT_NEAR(model2["effects"]["gps_latency"]["estimate"][0].get<double>(), 0.245, 0.02);
}

// The hard iron is always carried with a magnetometer (from zero; the first
// field sample seeds it): an airframe's 20 uT is followed, so nothing is
// missing, but the user is told, and --apply writes it.
TEST(Diagnose, AnAirframesHardIronIsFollowedAndTold) {
  TempDir dir;
  nlohmann::json model;
  const auto f = only_carried_finding(dir, R"({"mag_hard_iron": [20.0, -15.0, 10.0]})", "mag_hard_iron", model);
  ASSERT_FALSE(f.is_null());
  // Learnt to 0.1 uT in the evaluation's flights (sigma 0.04-0.2 uT); 1 uT is the reporting resolution.
  const double truth[3] = {20.0, -15.0, 10.0};
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(f["estimate"][i].get<double>(), truth[i], 1.0) << i;
}

TEST(Diagnose, NamesAHiddenGpsLatencyLeftOutOfTheModelAndTheErrorFalls) {
  TempDir dir;
  const auto d = diagnose(dir, R"({"gps_latency": 0.2})", {"--without-effects", "gps_latency"});
  ASSERT_EQ(d["missing_effects"].size(), 1u) << d.dump(1);
  EXPECT_EQ(d["missing_effects"][0], "gps_latency");
  // Estimated total latency = 0.045 s base + 0.2 s hidden; its sigma is ~0.007 s: 0.02 s is ~3 sigma.
  EXPECT_NEAR(first_candidate(d)["estimate"][0].get<double>(), 0.245, 0.02);
  EXPECT_LT(d["after"]["rmse_pos_h_m"].get<double>(), 0.5 * d["before"]["rmse_pos_h_m"].get<double>());
}

TEST(Diagnose, NamesAHiddenLeverArm) {
  TempDir dir;
  const auto d = diagnose(dir, R"({"lever_arm": [0.9, -0.5, -0.6]})");
  ASSERT_GE(d["missing_effects"].size(), 1u) << d.dump(1);
  EXPECT_EQ(d["missing_effects"][0], "lever_arm");
  // Sigmas 0.04-0.15 m: the lever arm shows only through rotations.
  expect_within_3_sigma(first_candidate(d), {0.9, -0.5, -0.6});
  EXPECT_LT(d["after"]["rmse_pos_h_m"].get<double>(), d["before"]["rmse_pos_h_m"].get<double>());
}

// The next flight of a unit starts from the model file of the last one: what
// it already knows is not a candidate again, and --apply writes it back with
// the new flight's estimates next to what this flight found (before, the
// written file held only the new effects: a third flight lost the first's).
TEST(Diagnose, ASecondFlightFromAModelFileKeepsTheKnownEffects) {
  TempDir dir;
  const std::string known = dir.write(
      "known.json", R"({"effects": {"gyro_misalign": {"estimate": [0, 0, 0, 0, 0, 0],
                                                       "sigma": [0.005, 0.005, 0.005, 0.005, 0.005, 0.005]}}})");
  const auto d = diagnose(dir, R"({"lever_arm": [0.9, -0.5, -0.6]})", {"--model-file", known, "--apply"});
  ASSERT_GE(d["missing_effects"].size(), 1u) << d.dump(1);
  EXPECT_EQ(d["missing_effects"][0], "lever_arm");
  for (const auto& c : d["rounds"][0]["candidates"]) {
    // Tried again only as "has it changed since the file?", and it has not.
    if (c["effect"] != "gyro_misalign") continue;
    EXPECT_TRUE(c["changed_since_model_file"].get<bool>()) << "tried again as a new effect";
    EXPECT_FALSE(c["explains"].get<bool>()) << c.dump();
  }
  std::ifstream in((dir.path() / "diag" / "model.json").string());
  const auto m = nlohmann::json::parse(in);
  ASSERT_TRUE(m["effects"].contains("gyro_misalign")) << m.dump(1);
  ASSERT_TRUE(m["effects"].contains("lever_arm")) << m.dump(1);
  // This flight's estimate of the known effect, not the file's prior: the
  // turns of a 10-minute flight pin a misalignment to 1-3 mrad.
  EXPECT_LT(m["effects"]["gyro_misalign"]["sigma"][0].get<double>(), 0.005);
}

// The unit's antenna moved since the flight its model file came from: the
// file's lever arm (at the IMU, 2 cm sigma) is learnt again from the
// vocabulary's prior and named as changed; an unchanged one is not.
TEST(Diagnose, AModelFileEffectThatChangedIsNamedAsChanged) {
  TempDir dir;
  const std::string moved = dir.write(
      "moved.json", R"({"effects": {"lever_arm": {"estimate": [0, 0, 0], "sigma": [0.02, 0.02, 0.02]}}})");
  const auto d = diagnose(dir, R"({"lever_arm": [0.9, -0.5, -0.6]})", {"--model-file", moved, "--apply"});
  ASSERT_EQ(d["changed_effects"].size(), 1u) << d.dump(1);
  EXPECT_EQ(d["changed_effects"][0], "lever_arm");
  EXPECT_EQ(d["missing_effects"].size(), 0u) << "the file's effect named as a new one";
  const auto& c = first_candidate(d);
  ASSERT_TRUE(c["changed_since_model_file"].get<bool>()) << c.dump();
  // Where the antenna is now (sigmas 0.05-0.2 m, as for a new lever arm).
  expect_within_3_sigma(c, {0.9, -0.5, -0.6});
  EXPECT_LT(d["after"]["rmse_pos_h_m"].get<double>(), d["before"]["rmse_pos_h_m"].get<double>());
  // The next flight starts from where the antenna is now.
  std::ifstream in((dir.path() / "diag" / "model.json").string());
  const auto m = nlohmann::json::parse(in);
  EXPECT_LT(m["effects"]["lever_arm"]["estimate"][2].get<double>(), -0.3) << m.dump(1);

  // Same flight, a file that has it right (within its sigmas): nothing changed.
  const std::string same = dir.write(
      "same.json", R"({"effects": {"lever_arm": {"estimate": [0.9, -0.5, -0.6], "sigma": [0.1, 0.1, 0.05]}}})");
  const std::string out = (dir.path() / "diag2").string();
  const auto r = run_sinu({"diagnose", "--in", (dir.path() / "flight").string(), "--gps-latency", "0.045", "--rounds",
                           "1", "--model-file", same, "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in2(out + "/diagnosis.json");
  const auto d2 = nlohmann::json::parse(in2);
  EXPECT_EQ(d2["changed_effects"].size(), 0u) << d2.dump(1);

  // --candidates limits the re-learnt candidates too: the moved antenna is not
  // tried (nor named) when the user asks only about the accelerometer scale.
  const std::string out3 = (dir.path() / "diag3").string();
  const auto r3 = run_sinu({"diagnose", "--in", (dir.path() / "flight").string(), "--gps-latency", "0.045", "--rounds",
                            "1", "--model-file", moved, "--candidates", "accel_scale", "--out", out3});
  ASSERT_EQ(r3.exit_code, 0) << r3.err;
  std::ifstream in3(out3 + "/diagnosis.json");
  const auto d3 = nlohmann::json::parse(in3);
  EXPECT_EQ(d3["changed_effects"].size(), 0u) << d3.dump(1);
  for (const auto& tried : d3["rounds"][0]["candidates"]) EXPECT_EQ(tried["effect"], "accel_scale") << tried.dump();
}

TEST(Diagnose, NamesAHiddenSoftIronAndTheHeadingRecovers) {
  TempDir dir;
  const auto d = diagnose(dir, R"({"mag_soft_iron": [[1.1, 0.03, 0], [0.03, 0.92, 0.02], [0, 0.02, 1.05]]})");
  ASSERT_GE(d["missing_effects"].size(), 1u) << d.dump(1);
  EXPECT_EQ(d["missing_effects"][0], "mag_soft_iron");
  // D = S - I, states xx yy zz xy xz yz. The diagonal is tied to the Earth-field
  // estimate (a common scale trades against |F|), so only shape is checked there;
  // the off-diagonal xy term is sharp (sigma ~0.001).
  const auto& est = first_candidate(d)["estimate"];
  EXPECT_GT(est[0].get<double>() - est[1].get<double>(), 0.1);  // xx - yy: truth 0.18
  EXPECT_NEAR(est[3].get<double>(), 0.03, 0.01);
}

// A compass mounted 2-3 deg off the IMU's axes: no symmetric soft iron
// explains a rotation, and before mag_misalign was in the vocabulary a gyro
// misalignment fitted it best (beyond what a real gyro has) and soft iron was
// named. Now the rotation is named and measured.
TEST(Diagnose, NamesAHiddenMagnetometerMisalignmentAndMeasuresIt) {
  TempDir dir;
  const double theta[3] = {0.035, -0.045, 0.03};  // rad
  const auto d = diagnose(dir, R"({"mag_misalign": [0.035, -0.045, 0.03]})");
  ASSERT_GE(d["missing_effects"].size(), 1u) << d.dump(1);
  EXPECT_EQ(d["missing_effects"][0], "mag_misalign");
  // The flight's banked turns determine every axis to a few mrad (sigma 2.6-3.2
  // mrad on this 10-minute flight, 0.5-0.9 on 20 minutes; the vertical axis
  // also trades against the declination, a state): each within 3 sigma, and
  // each sigma under 5 mrad, a tenth of the angles.
  const auto& c = first_candidate(d);
  for (std::size_t i = 0; i < 3; ++i) {
    const double sigma = c["sigma"][i].get<double>();
    EXPECT_LT(sigma, 5e-3) << c.dump();
    EXPECT_NEAR(c["estimate"][i].get<double>(), theta[i], 3.0 * sigma) << c.dump();
  }
}

// The motors' current makes a field that follows the thrust (an internal
// compass on a multirotor's power wiring: ArduPilot's compassmot). Put into
// an independent simulator's quadcopter, it was named mag_soft_iron: the
// vocabulary had no effect for it. Hidden here at [1.5, -1, 2] uT per m/s^2
// (2-8 uT through the flight's banked turns).
TEST(Diagnose, NamesAFieldThatFollowsTheThrust) {
  TempDir dir;
  const auto d = diagnose(dir, R"({"mag_motor_interference": [1.5, -1.0, 2.0]})");
  ASSERT_GE(d["missing_effects"].size(), 1u) << d.dump(1);
  EXPECT_EQ(d["missing_effects"][0], "mag_motor_interference");
  // A 20-minute flight measured them to 0.01 (sigma 0.01); 0.05 at least.
  expect_within_3_sigma(first_candidate(d), {1.5, -1.0, 2.0}, 0.05);
  EXPECT_LT(d["after"]["rmse_att_deg"].get<double>(), d["before"]["rmse_att_deg"].get<double>());
}

// A compass read over a slow path holds the field of an attitude tau ago
// (PX4's EKF2_MAG_DELAY; ArduPilot's EKF assumes 60 ms). Put into an
// independent simulator's quadcopter at 0.2 s, it was named mag_soft_iron
// (+4352) and a lever arm: the vocabulary had no effect for it. Hidden here
// at 0.15 s: in the flight's 10-20 deg/s turns, 1.5-3 deg of heading.
TEST(Diagnose, NamesALateMagnetometer) {
  TempDir dir;
  const auto d = diagnose(dir, R"({"mag_latency": 0.15})");
  ASSERT_GE(d["missing_effects"].size(), 1u) << d.dump(1);
  EXPECT_EQ(d["missing_effects"][0], "mag_latency");
  // Its sigma from the turns is a few ms; 5 ms at least.
  expect_within_3_sigma(first_candidate(d), {0.15}, 0.005);
  EXPECT_LT(d["after"]["rmse_att_deg"].get<double>(), d["before"]["rmse_att_deg"].get<double>());
}

// A receiver whose velocity is averaged over its fix interval reports the
// interval's middle: found on both real logs (the car's 4-Hz RTK receiver
// 0.126 s, half its period; docs/diagnose.md). Hidden at 0.15 s here.
TEST(Diagnose, NamesAHiddenVelocityLatencyAndMeasuresIt) {
  TempDir dir;
  const auto d = diagnose(dir, R"({"gps_velocity_latency": 0.15})", {"--apply"});
  ASSERT_GE(d["missing_effects"].size(), 1u) << d.dump(1);
  EXPECT_EQ(d["missing_effects"][0], "gps_velocity_latency");
  // No bench session given: the finding says the noise model was not this unit's.
  EXPECT_FALSE(d["calibrated"].get<bool>());
  EXPECT_NE(d.value("caution", "").find("without --calib"), std::string::npos) << d.dump(1);
  // The turns' 2-4 m/s^2 against 0.05 m/s of velocity noise at 5 Hz: a few
  // milliseconds (a tenth of the value is a wide bound; within 3 sigma).
  const auto& c = first_candidate(d);
  const double sigma = c["sigma"][0].get<double>();
  EXPECT_LT(sigma, 0.015) << c.dump();
  EXPECT_NEAR(c["estimate"][0].get<double>(), 0.15, 3.0 * sigma) << c.dump();

  // Once it is known, nothing is left to explain. The velocity is taken back
  // over its own lag with the INS's mean acceleration across it; with a
  // smoothed acceleration (0.2 s behind) every roll-in and speed change left
  // a misfit of tau x 0.2 s x the jerk, which the next round gave to another
  // effect (here an accelerometer scale, log-likelihood +5.0; a vertical
  // lever arm in three of the evaluation's twenty pairs).
  const std::string ds = (dir.path() / "flight").string(), out = (dir.path() / "again").string();
  const auto r = run_sinu({"diagnose", "--in", ds, "--gps-latency", "0.045", "--rounds", "1", "--model-file",
                           (dir.path() / "diag" / "model.json").string(), "--quiet", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out + "/diagnosis.json");
  const auto again = nlohmann::json::parse(in);
  EXPECT_TRUE(again["missing_effects"].empty()) << again["missing_effects"].dump();
}

// An IMU whose samples are stamped late (a sensor's filter delay, a driver's
// read latency, a recorder's clock) puts the fixes' time of validity after
// their arrival on its clock: the learnt latency goes below zero, which no
// receiver does. Diagnose says so, --apply writes the IMU's latency (the
// receiver's own taken as configured), and the replay from the model file
// is stamped at the instants it describes. Seed 9's flight with its imu.csv
// 0.1 s late: the receiver's 45 ms is configured, so the IMU's latency
// should come out 0.1 s; 10 ms is a fifth of the learnt latency's 3-sigma
// (its sigma about 3 ms at 40 m/s) plus the receiver's sentence spacing.
TEST(Diagnose, ImuStampsLateAreToldAndTheModelFileTakesThemBack) {
  TempDir dir;
  const std::string ds = dir.file("flight"), late = dir.file("late");
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", ds, "--seed", "9", "--duration", "600"}).exit_code, 0);
  std::filesystem::create_directories(late);
  std::filesystem::copy_file(ds + "/gps.nmea", late + "/gps.nmea");
  std::filesystem::copy_file(ds + "/truth.csv", late + "/truth.csv");
  {
    std::ifstream in(ds + "/imu.csv");
    std::ofstream out(late + "/imu.csv");
    std::string line;
    std::getline(in, line);
    out << line << "\n";
    while (std::getline(in, line)) {
      const std::size_t comma = line.find(',');
      char t[32];
      std::snprintf(t, sizeof t, "%.6f", std::stod(line.substr(0, comma)) + 0.1);
      out << t << line.substr(comma) << "\n";
    }
  }
  const auto r = run_sinu({"diagnose", "--in", late, "--gps-latency", "0.045", "--rounds", "1", "--apply", "--quiet",
                           "--out", dir.file("diag")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("the IMU's samples are stamped late"), std::string::npos) << r.out;
  std::ifstream m(dir.file("diag") + "/model.json");
  const auto model = nlohmann::json::parse(m);
  ASSERT_TRUE(model.contains("imu_latency_s")) << model.dump(1);
  EXPECT_NEAR(model["imu_latency_s"].get<double>(), 0.1, 0.01);
  // Replayed as it is, the solution is 0.1 s behind the truth (4 m at 40 m/s); from the model file it is not.
  const auto as_is = run_sinu({"replay", "--in", late, "--gps-latency", "0.045", "--quiet", "--out", dir.file("r0")});
  const auto fixed =
      run_sinu({"replay", "--in", late, "--model-file", dir.file("diag") + "/model.json", "--quiet", "--out", dir.file("r1")});
  ASSERT_EQ(as_is.exit_code, 0) << as_is.err;
  ASSERT_EQ(fixed.exit_code, 0) << fixed.err;
  std::ifstream a(dir.file("r0") + "/summary.json"), b(dir.file("r1") + "/summary.json");
  const auto s0 = nlohmann::json::parse(a), s1 = nlohmann::json::parse(b);
  EXPECT_LT(s1["rmse"]["pos_h_m"].get<double>(), 0.5 * s0["rmse"]["pos_h_m"].get<double>())
      << s0["rmse"].dump() << " " << s1["rmse"].dump();
}

// --outage as in replay: the candidates are judged on all the data (an
// outage's re-convergence is no misfit to explain), and the drift in the
// windows is shown for the model before and after: the error falls.
TEST(Diagnose, WithOutagesTheEffectIsStillNamedAndItsOutageDriftFalls) {
  TempDir dir;
  // A 2-3 % gyro scale: what the simulator draws for it (docs/simulation.md).
  const std::string ds = dir.file("flight"), effects = dir.file("effects.json");
  std::ofstream(effects) << R"({"gyro_scale": [20000, -15000, 25000]})";
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", ds, "--seed", "33", "--duration", "900", "--effects", effects})
                .exit_code,
            0);
  const double t0 = first_t(ds);
  std::string outages;
  for (const double at : {200.0, 400.0, 600.0, 800.0}) {
    if (!outages.empty()) outages += ',';
    outages += std::to_string(t0 + at) + ":30";
  }
  const auto r = run_sinu({"diagnose", "--in", ds, "--rounds", "1", "--outage", outages, "--quiet", "--out",
                           dir.file("diag")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(dir.file("diag") + "/diagnosis.json");
  const auto d = nlohmann::json::parse(in);
  ASSERT_GE(d["missing_effects"].size(), 1u) << d.dump(1);
  EXPECT_EQ(d["missing_effects"][0], "gyro_scale");
  const double before = d["before"]["outage_drift_h_m"].get<double>(), after = d["after"]["outage_drift_h_m"].get<double>();
  // Measured 45.6 -> 20.4 m over four 30-s outages: the scale error turns the
  // heading in every turn; a third less is well inside what it explains.
  EXPECT_GT(before, 0.0);
  EXPECT_LT(after, 0.67 * before);
  EXPECT_NE(r.out.find("outage drift"), std::string::npos) << r.out;
}

TEST(Diagnose, NamesNothingOnAFlightWithoutAHiddenEffect) {
  TempDir dir;
  const auto d = diagnose(dir, "");
  EXPECT_EQ(d["missing_effects"].size(), 0u) << d.dump(1);
  EXPECT_FALSE(d.contains("caution")) << "nothing named, nothing to doubt: " << d.dump(1);
  EXPECT_EQ(d["carried_findings"].size(), 0u) << "the configured latency is the simulator's, no hard iron: " << d.dump(1);
  for (const auto& c : d["rounds"][0]["candidates"]) EXPECT_FALSE(c["explains"].get<bool>()) << c.dump();
}

// What the IMU did not measure is no effect of the unit: 1 s of the
// accelerometer pegged at 2 g (a hard landing's bump) and a 3-s gap in
// imu.csv. Diagnose names no effect for them, and says so: the counts in
// diagnosis.json and a "data:" line (before it, a clipping flight's report
// never mentioned the clipping).
TEST(Diagnose, WhatTheImuDidNotMeasureIsToldAndNotNamedAsAnEffect) {
  TempDir dir;
  const std::string ds = (dir.path() / "flight").string(), out = (dir.path() / "diag").string();
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", ds, "--seed", "9", "--duration", "600"}).exit_code, 0);
  const double t0 = first_t(ds);
  ImuClip clip;
  clip.start_s = t0 + 300.0;
  clip.duration_s = 1.0;
  ImuGap gap;
  gap.start_s = t0 + 400.0;
  gap.duration_s = 3.0;
  inject_faults(ds, ds, {clip, gap});
  const auto r = run_sinu({"diagnose", "--in", ds, "--gps-latency", "0.045", "--rounds", "1", "--accel-range", "2",
                           "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out + "/diagnosis.json");
  const auto d = nlohmann::json::parse(in);
  EXPECT_EQ(d["missing_effects"].size(), 0u) << d.dump(1);
  // 40 Hz: 1 s pegged is 40 samples (the range's edge counts as clipped, so
  // the neighbours of the window may add one or two).
  EXPECT_GE(d["imu_faults"]["clipped_samples"].get<int>(), 40) << d["imu_faults"].dump();
  EXPECT_LE(d["imu_faults"]["clipped_samples"].get<int>(), 44) << d["imu_faults"].dump();
  EXPECT_EQ(d["imu_faults"]["gaps"].get<int>(), 1) << d["imu_faults"].dump();
  // The interval across the gap: the 3 s removed plus one 25-ms sample period.
  EXPECT_NEAR(d["imu_faults"]["longest_gap_s"].get<double>(), 3.025, 0.001) << d["imu_faults"].dump();
  EXPECT_NE(r.out.find("data: the IMU has "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("at full scale"), std::string::npos) << r.out;
}

double outage_drift(const std::string& summary) {
  std::ifstream in(summary);
  return nlohmann::json::parse(in)["outage_max_drift_h_rms_m"].get<double>();
}

// A gyro misalignment (no states before issue 13), as the evaluation runs it:
// a 20-minute flight, a bench hour of the same unit for calib.json, diagnose
// without truth. It is named with its six terms; --apply writes them to a
// model file, and a replay started from it drifts less in GPS outages, as
// much as one given the true effect's states.
TEST(Diagnose, NamesAHiddenGyroMisalignmentAndTheAppliedModelLowersTheOutageDrift) {
  TempDir dir;
  const std::string ds = dir.file("flight"), bench = dir.file("bench"), calib = dir.file("calib.json");
  const std::string effects = dir.write("effects.json",
                                        R"({"gyro_misalign": [[0, 0.010, -0.008], [0.012, 0, 0.009], [-0.011, 0.007, 0]]})");
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", ds, "--seed", "21", "--duration", "1200", "--effects", effects})
                .exit_code, 0);
  std::filesystem::rename(ds + "/truth.csv", dir.file("truth.csv"));
  ASSERT_EQ(run_sinu({"simulate", "static", "--out", bench, "--seed", "21", "--hours", "1"}).exit_code, 0);
  ASSERT_EQ(run_sinu({"calibrate", "--in", bench, "--out", calib, "--quiet"}).exit_code, 0);
  const std::string out = dir.file("diag");
  const auto r = run_sinu({"diagnose", "--in", ds, "--calib", calib, "--rounds", "1", "--apply", "--quiet", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out + "/diagnosis.json");
  const auto d = nlohmann::json::parse(in);
  ASSERT_GE(d["missing_effects"].size(), 1u) << d.dump(1);
  EXPECT_EQ(d["missing_effects"][0], "gyro_misalign");
  EXPECT_TRUE(d["calibrated"].get<bool>());
  EXPECT_FALSE(d.contains("caution")) << "the unit's own noise model: " << d.dump(1);
  // xy xz yx yz zx zy; sigmas 1.2-2.7 mrad: a 20-minute flight's turns.
  expect_within_3_sigma(first_candidate(d), {0.010, -0.008, 0.012, 0.009, -0.011, 0.007});
  EXPECT_NE(r.out.find("applied: " + out + "/model.json"), std::string::npos) << r.out;

  // Four 30-s outages; the same replay without, from the model file, and given the true states.
  std::ifstream imu(ds + "/imu.csv");
  std::string line;
  std::getline(imu, line);
  std::getline(imu, line);
  const double t0 = std::stod(line);
  char outages[160];
  std::snprintf(outages, sizeof outages, "%.3f:30,%.3f:30,%.3f:30,%.3f:30", t0 + 300.0, t0 + 500.0, t0 + 700.0,
                t0 + 900.0);
  auto replay = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> a = {"replay", "--in", ds, "--truth", dir.file("truth.csv"), "--calib", calib,
                                  "--outage", outages, "--quiet", "--out", dir.file(name)};
    a.insert(a.end(), extra.begin(), extra.end());
    EXPECT_EQ(run_sinu(a).exit_code, 0);
    return outage_drift(dir.file(name) + "/summary.json");
  };
  const double baseline = replay("r0", {}), applied = replay("r1", {"--model-file", out + "/model.json"}),
               true_model = replay("r2", {"--effects", "gyro_misalign"});
  // Measured 20.5 -> 14.8 m (true model 14.6 m): the model file must recover
  // most of it, and come within 15 % of the true model (the issue's target).
  EXPECT_LT(applied, 0.85 * baseline);
  EXPECT_LT(applied, 1.15 * true_model);
}

// A noise level set too small is a diagnosis, not an effect: a magnetometer
// sigma of 0.2 uT fixed on a unit whose field noise is ~0.4 uT makes every
// flight phase misfit alike (NIS ~4); diagnose says so, by how much, and names
// no effect (before, soft iron was named: fitting noise).
TEST(Diagnose, ANoiseLevelSetTooSmallIsNamedAsNoiseNotAsAnEffect) {
  TempDir dir;
  const std::string ds = dir.file("flight"), out = dir.file("diag");
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", ds, "--seed", "9", "--duration", "600"}).exit_code, 0);
  const auto r = run_sinu({"diagnose", "--in", ds, "--gps-latency", "0.045", "--rounds", "1", "--mag-sigma", "0.2",
                           "--quiet", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out + "/diagnosis.json");
  const auto d = nlohmann::json::parse(in);
  EXPECT_EQ(d["missing_effects"].size(), 0u) << d.dump(1);
  const std::size_t at = r.out.find("noise: magnetometer sigma 0.2 uT was set ");
  ASSERT_NE(at, std::string::npos) << r.out;
  // The factor: measured 2.03 (the simulator's field noise and disturbance ~0.4 uT);
  // 1.5-3 separates "about twice too small" from no finding or a wild guess.
  const double factor = std::stod(r.out.substr(at + std::string("noise: magnetometer sigma 0.2 uT was set ").size()));
  EXPECT_GT(factor, 1.5);
  EXPECT_LT(factor, 3.0);
  EXPECT_NE(r.out.find("x too small", at), std::string::npos) << r.out;
}

// A receiver whose GST is generous (the real quadcopter's u-blox: NIS 0.05)
// hides effects the filter would see; diagnose says by how much and replays
// with the stated sigma scaled back. Here the simulator's receiver states its
// sigma honestly and the replay takes it 4x too large.
TEST(Diagnose, AGenerousReceiverSigmaIsFoundAndScaledBack) {
  TempDir dir;
  const std::string ds = dir.file("flight"), out = dir.file("diag");
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", ds, "--seed", "9", "--duration", "600"}).exit_code, 0);
  const auto r = run_sinu({"diagnose", "--in", ds, "--gps-latency", "0.045", "--rounds", "1", "--gps-pos-sigma-scale",
                           "4", "--quiet", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string said = "noise: GNSS position sigma (the receiver's GST, or HDOP x UERE) is ";
  const std::size_t at = r.out.find(said);
  ASSERT_NE(at, std::string::npos) << r.out;
  // 4x too large, read from the innovations; the 0.2-m sigma floor and the
  // receiver's correlated error (a state whose prior scales with the sigma)
  // keep the NIS from being exactly 1/16: 2.5-6 tells "about 4" from no finding.
  const double factor = std::stod(r.out.substr(at + said.size()));
  EXPECT_GT(factor, 2.5);
  EXPECT_LT(factor, 6.0);
  EXPECT_NE(r.out.find("x too large", at), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("diagnosed with --gps-pos-sigma-scale ", at), std::string::npos) << r.out;
}

// What this flight cannot test is skipped, with the reason: no temperature
// in imu.csv, no temperature coefficients.
TEST(Diagnose, CandidatesTheDataCannotTestAreSkippedWithTheReason) {
  TempDir dir;
  const std::string ds = dir.file("flight");
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", ds, "--seed", "9", "--duration", "600"}).exit_code, 0);
  // Empty the temp field (the last) of every imu.csv row: "no measurement" (dataset contract).
  {
    std::ifstream in(ds + "/imu.csv");
    std::ofstream out(ds + "/imu_no_temp.csv");
    std::string line;
    std::getline(in, line);
    out << line << "\n";
    while (std::getline(in, line)) out << line.substr(0, line.rfind(',') + 1) << "\n";
  }
  std::filesystem::rename(ds + "/imu_no_temp.csv", ds + "/imu.csv");
  const std::string out = dir.file("diag");
  const auto r = run_sinu({"diagnose", "--in", ds, "--gps-latency", "0.045", "--rounds", "1", "--quiet", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out + "/diagnosis.json");
  const auto d = nlohmann::json::parse(in);
  std::vector<std::string> skipped;
  for (const auto& s : d["skipped"]) {
    skipped.push_back(s["effect"]);
    EXPECT_NE(s["reason"].get<std::string>().find("no temperature in imu.csv"), std::string::npos) << s.dump();
  }
  EXPECT_EQ(skipped, (std::vector<std::string>{"accel_temp_bias", "gyro_temp_bias"}));
  for (const auto& c : d["rounds"][0]["candidates"]) EXPECT_EQ(c["effect"].get<std::string>().find("temp"), std::string::npos);
  EXPECT_NE(r.out.find("not tested: accel_temp_bias (no temperature in imu.csv"), std::string::npos) << r.out;
}

TEST(Diagnose, ABadModelFileIsAnErrorNamingTheFileAndTheKey) {
  TempDir dir;
  const std::string ds = dir.file("flight");
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", ds, "--seed", "9", "--duration", "300"}).exit_code, 0);
  const std::string bad = dir.write("model.json", R"({"effects": {"gyro_misalign": {"estimate": [0, 0, 0], "sigma": [1, 1, 1]}}})");
  const auto r = run_sinu({"replay", "--in", ds, "--model-file", bad, "--quiet", "--out", dir.file("r")});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(bad + ": effects.gyro_misalign.estimate: expected 6 finite numbers"), std::string::npos) << r.err;
  const std::string unknown = dir.write("m2.json", R"({"effects": {"warp_drive": {"estimate": [1], "sigma": [1]}}})");
  const auto u = run_sinu({"replay", "--in", ds, "--model-file", unknown, "--quiet", "--out", dir.file("r2")});
  EXPECT_NE(u.exit_code, 0);
  EXPECT_NE(u.err.find(unknown + ": effects.warp_drive: unknown effect"), std::string::npos) << u.err;
}

// The real quadcopter (an autopilot's already calibrated IMU, truth = the
// autopilot's EKF, a peer): what is named must be physically plausible (before
// the vocabulary's plausible maxima a 3.6 % gyro scale and a 92 mrad gyro
// misalignment were named here), and applying it lowers the error against
// the peer.
TEST(Diagnose, OnTheRealQuadcopterOnlyPlausibleEffectsAreNamedAndTheErrorFalls) {
  SINU_REQUIRE_SHARED(uav, "data/real/uav_log171");
  TempDir dir;
  const std::string out = dir.file("diag");
  const auto r = run_sinu({"diagnose", "--in", uav, "--quiet", "--apply", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out + "/diagnosis.json");
  const auto d = nlohmann::json::parse(in);
  for (const auto& name : d["missing_effects"]) {
    EXPECT_NE(name, "gyro_scale");
    EXPECT_NE(name, "gyro_misalign");
    EXPECT_NE(name, "accel_misalign");
  }
  for (const auto& round : d["rounds"]) {
    for (const auto& c : round["candidates"]) {
      if (c["explains"].get<bool>()) {
        EXPECT_LE(c["plausibility"].get<double>(), 1.0) << c.dump();
      }
    }
  }
  EXPECT_NE(r.out.find("not named: gyro_misalign would fit"), std::string::npos) << r.out;
  // Applied as a user would (the next replay starts from the model file), the
  // error against the autopilot's EKF falls: measured 0.425 -> 0.424 m and
  // 4.86 -> 3.99 deg (soft iron and a 60/35 mrad magnetometer misalignment;
  // session 14, soft iron and an 11 cm lever arm: 0.397 m, 3.82 deg). Since
  // session 23 the velocity's latency (0.166 s) is named after the soft iron:
  // 0.425 -> 0.462 m, 4.86 -> 3.75 deg. The attitude must fall; the horizontal
  // distance from a peer that fuses its receiver's velocity as of the
  // position's time rose by 4 cm, so it is held to the issue's target (0.6 m)
  // instead of to a fall.
  const auto before = run_sinu({"replay", "--in", uav, "--quiet", "--out", dir.file("before")});
  const auto after =
      run_sinu({"replay", "--in", uav, "--model-file", out + "/model.json", "--quiet", "--out", dir.file("after")});
  ASSERT_EQ(before.exit_code, 0) << before.err;
  ASSERT_EQ(after.exit_code, 0) << after.err;
  std::ifstream b(dir.file("before") + "/summary.json"), a(dir.file("after") + "/summary.json");
  const auto sb = nlohmann::json::parse(b), sa = nlohmann::json::parse(a);
  EXPECT_LT(sa["rmse"]["pos_h_m"].get<double>(), 0.6);
  EXPECT_LT(sa["rmse"]["att_deg"].get<double>(), sb["rmse"]["att_deg"].get<double>());
}

// tools/diagnose_fleet.sh over a folder of two flights: a diagnosis each
// (GNU parallel), and the fleet table naming the hidden lever arm in one unit.
TEST(Diagnose, TheFleetScriptDiagnosesEveryFlightAndTablesTheEffects) {
  if (::access("/usr/bin/parallel", X_OK) != 0) GTEST_SKIP() << "GNU parallel missing (tools/setup.sh installs it)";
  TempDir dir;
  const std::string logs = dir.file("logs"), out = dir.file("out");
  std::filesystem::create_directories(logs);
  const std::string lever = dir.write("lever.json", R"({"lever_arm": [0.9, -0.5, -0.6]})");
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", logs + "/unit_a", "--seed", "9", "--duration", "600", "--effects",
                      lever}).exit_code, 0);
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", logs + "/unit_b", "--seed", "9", "--duration", "600"}).exit_code, 0);
  ::setenv("SINU", SINU_EXE, 1);
  const auto r = run_process({std::string(SINU_SOURCE_DIR) + "/tools/diagnose_fleet.sh", logs, out, "--gps-latency",
                              "0.045", "--rounds", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string table = read_file(out + "/fleet.md");
  EXPECT_NE(table.find("# Fleet diagnosis: 2 flights"), std::string::npos) << table;
  EXPECT_NE(table.find("| `lever_arm` | 1 | 50 % | unit_a: ["), std::string::npos) << table;
  EXPECT_TRUE(std::filesystem::exists(out + "/unit_b/diagnosis.json"));
  EXPECT_TRUE(std::filesystem::exists(out + "/unit_a/model.json"));
}

TEST(Diagnose, BadInputIsAnErrorNamingTheProblem) {
  TempDir dir;
  const auto r = run_sinu({"diagnose", "--in", (dir.path() / "missing").string(), "--out", (dir.path() / "o").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("missing"), std::string::npos) << r.err;
  const auto u = run_sinu({"diagnose", "--in", "x", "--out", "y", "--candidates", "warp_drive"});
  EXPECT_EQ(u.exit_code, 2);
  EXPECT_NE(u.err.find("warp_drive"), std::string::npos) << u.err;
}

}  // namespace
}  // namespace sinu::test
