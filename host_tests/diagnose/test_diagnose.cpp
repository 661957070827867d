// sinu diagnose on simulated flights with a hidden effect (the simulator's
// effect vocabulary): it must name the effect that is in the data, estimate
// it, and the error must fall when it is added; on a flight without an effect
// it must name nothing.
#include <gtest/gtest.h>

#include <fstream>
#include <vector>
#include <nlohmann/json.hpp>

#include "host_tests/support/run_process.hpp"
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

TEST(Diagnose, TheDefaultModelEstimatesAHiddenGpsLatency) {
  // gps_latency is one of the default states: the baseline finds it and nothing is missing.
  TempDir dir;
  const auto d = diagnose(dir, R"({"gps_latency": 0.2})");
  EXPECT_EQ(d["missing_effects"].size(), 0u) << d.dump(1);
  std::ifstream in((dir.path() / "diag" / "baseline" / "summary.json").string());
  const auto s = nlohmann::json::parse(in);
  bool found = false;
  for (const auto& e : s["effects"]) {
    if (e["name"] != "gps_latency") continue;
    found = true;
    // 0.045 s base + 0.2 s hidden; sigma ~0.005 s: 0.02 s is 4 sigma.
    EXPECT_NEAR(e["estimate"][0].get<double>(), 0.245, 0.02);
  }
  EXPECT_TRUE(found);
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
  const auto& c = first_candidate(d);
  const double truth[3] = {0.9, -0.5, -0.6};
  for (std::size_t i = 0; i < 3; ++i) {
    // Within 3 sigma of the truth (sigmas 0.04-0.15 m: the lever arm shows only through rotations).
    EXPECT_NEAR(c["estimate"][i].get<double>(), truth[i], 3.0 * c["sigma"][i].get<double>()) << "axis " << i;
  }
  EXPECT_LT(d["after"]["rmse_pos_h_m"].get<double>(), d["before"]["rmse_pos_h_m"].get<double>());
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

TEST(Diagnose, NamesNothingOnAFlightWithoutAHiddenEffect) {
  TempDir dir;
  const auto d = diagnose(dir, "");
  EXPECT_EQ(d["missing_effects"].size(), 0u) << d.dump(1);
  for (const auto& c : d["rounds"][0]["candidates"]) EXPECT_FALSE(c["explains"].get<bool>()) << c.dump();
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
