// sinu calibrate on multi-position sessions end to end: the calib.json
// section and the printed report, several --in (one face each), a session
// with too few faces, a level session as before; and replay refusing a
// malformed section with the key named.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace {

using nlohmann::json;
using sinu::test::read_file;
using sinu::test::run_sinu;
using sinu::test::TempDir;

json read_json(const std::string& path) { return json::parse(read_file(path)); }

// The rows of `dataset`/imu.csv with t in [from, to] as a dataset of their own.
std::string cut(const TempDir& tmp, const std::string& dataset, const std::string& name, double from, double to) {
  const std::string dir = tmp.file(name);
  std::filesystem::create_directories(dir);
  std::ifstream in(dataset + "/imu.csv");
  std::ofstream out(dir + "/imu.csv");
  std::string line;
  std::getline(in, line);
  out << line << "\n";
  while (std::getline(in, line)) {
    const double t = std::stod(line.substr(0, line.find(',')));
    if (t >= from && t <= to) out << line << "\n";
  }
  return dir;
}

// One 14-position session (2 min per position), calibrated once for the checks below.
class PositionsSession : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    const auto sim = run_sinu({"simulate", "static", "--out", dir_->file("bench"), "--seed", "77", "--positions", "14",
                               "--hold-s", "120", "--hidden-out", dir_->file("hidden.json")});
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    const json site = read_json(dir_->file("hidden.json"))["site"];
    cal_ = new sinu::test::ProcessResult(
        run_sinu({"calibrate", "--in", dir_->file("bench"), "--out", dir_->file("calib.json"), "--latitude",
                  std::to_string(site["lat_deg"].get<double>()), "--height",
                  std::to_string(site["ground_h_m"].get<double>()), "--quiet"}));
  }
  static void TearDownTestSuite() {
    delete dir_;
    delete cal_;
    dir_ = nullptr;
    cal_ = nullptr;
  }
  static TempDir* dir_;
  static sinu::test::ProcessResult* cal_;
};
TempDir* PositionsSession::dir_ = nullptr;
sinu::test::ProcessResult* PositionsSession::cal_ = nullptr;

TEST_F(PositionsSession, CalibJsonHasTheSectionAndTheNoiseModels) {
  ASSERT_EQ(cal_->exit_code, 0) << cal_->err;
  const json c = read_json(dir_->file("calib.json"));
  // Everything calib.json always had (the EKF's noise models) ...
  for (const char* ax : {"ax", "ay", "az", "gx", "gy", "gz"}) {
    ASSERT_TRUE(c["axes"].contains(ax)) << ax;
    EXPECT_TRUE(c["axes"][ax].contains("model")) << ax;
  }
  // ... fitted on the longest hold (2 min less the trimmed ends), not the 30-min session.
  EXPECT_LT(c["sessions"][0]["duration_s"].get<double>(), 120.0);
  const json& s = c["six_position"];
  EXPECT_EQ(s["segments_used"], 14);
  EXPECT_EQ(s["attitudes"], 14);
  EXPECT_EQ(s["parameters"], 9);
  EXPECT_TRUE(s["misalign_fitted"].get<bool>());
  EXPECT_TRUE(s["latitude_given"].get<bool>());
  EXPECT_EQ(s["segments"].size(), 14u);
  EXPECT_EQ(s["noise_models_from"][0]["span"], "longest still segment");
  for (const char* k : {"accel_bias", "accel_bias_sigma", "accel_scale", "accel_scale_sigma", "gyro_bias",
                        "gyro_bias_sigma"})
    EXPECT_EQ(s[k].size(), 3u) << k;
  EXPECT_EQ(s["accel_misalign"].size(), 3u);
  // The values: each within 5 of its own sigmas of the hidden unit (scale to
  // first order: the hidden misalignment's second-order terms are below 250
  // ppm and the sigmas with 2-min holds are several hundred ppm), the
  // symmetric misalignment likewise.
  const json h = read_json(dir_->file("hidden.json"));
  for (std::size_t i = 0; i < 3; ++i) {
    const double e = s["accel_scale"][i].get<double>() - h["effects"]["accel_scale"][i].get<double>();
    EXPECT_LT(std::abs(e), 5.0 * s["accel_scale_sigma"][i].get<double>() + 250.0) << i;
    const double b = s["accel_bias"][i].get<double>() - h["imu_error_model"]["accel"]["turn_on_bias"][i].get<double>();
    EXPECT_LT(std::abs(b), 5.0 * s["accel_bias_sigma"][i].get<double>()) << i;
  }
  const json& M = h["effects"]["accel_misalign"];
  const double xy = 0.5 * (M[0][1].get<double>() + M[1][0].get<double>());
  EXPECT_LT(std::abs(s["accel_misalign"][0][1].get<double>() - xy),
            5.0 * s["accel_misalign_sigma"][0][1].get<double>() + 2e-4);
  // The printed report.
  EXPECT_NE(cal_->out.find("six-position: 14 still segments in 14 attitudes"), std::string::npos) << cal_->out;
  EXPECT_NE(cal_->out.find("accel scale"), std::string::npos) << cal_->out;
  EXPECT_NE(cal_->out.find("not observable from gravity"), std::string::npos) << cal_->out;
}

// The same holds recorded one face per --in give the same calibration: the
// means differ by about a second at each end, and the weights come from each
// face's own Allan deviation instead of the longest hold's, so the two fits of
// nearly the same data differ by a fraction of their sigma (within one).
TEST_F(PositionsSession, OneFacePerInputGivesTheSameFit) {
  ASSERT_EQ(cal_->exit_code, 0) << cal_->err;
  const json h = read_json(dir_->file("hidden.json"));
  const json site = h["site"];
  std::vector<std::string> args = {"calibrate", "--out", dir_->file("faces.json"), "--quiet", "--latitude",
                                   std::to_string(site["lat_deg"].get<double>()), "--height",
                                   std::to_string(site["ground_h_m"].get<double>())};
  for (std::size_t k = 0; k < 14; ++k) {
    const json& p = h["positions"][k];
    args.push_back("--in");
    args.push_back(cut(*dir_, dir_->file("bench"), "face" + std::to_string(k), p["still_from_t"].get<double>() + 2.0,
                       p["still_to_t"].get<double>() - 2.0));
  }
  const auto r = run_sinu(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json one = read_json(dir_->file("calib.json"))["six_position"];
  const json many = read_json(dir_->file("faces.json"))["six_position"];
  EXPECT_EQ(many["segments_used"], 14);
  EXPECT_EQ(many["noise_models_from"][0]["span"], "whole session") << "a face per input: each one attitude";
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(many["accel_scale"][i].get<double>(), one["accel_scale"][i].get<double>(),
                one["accel_scale_sigma"][i].get<double>())
        << i;
  }
}

TEST_F(PositionsSession, TooFewFacesIsAnErrorThatNamesTheMissingOnes) {
  const json h = read_json(dir_->file("hidden.json"));
  // The first four positions (and the turns between them).
  const std::string four = cut(*dir_, dir_->file("bench"), "four", h["positions"][0]["still_from_t"].get<double>(),
                               h["positions"][3]["still_to_t"].get<double>());
  const auto r = run_sinu({"calibrate", "--in", four, "--out", dir_->file("four.json"), "--quiet"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("held still in 4 attitudes (-z up, +x up, +y up, -x up)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("too few faces"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("missing: -y up, +z up"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir_->file("four.json")));
}

// A level session: the calibration of the whole session, no new section.
TEST(PositionsCli, ALevelSessionIsCalibratedAsBefore) {
  TempDir tmp;
  ASSERT_EQ(run_sinu({"simulate", "static", "--out", tmp.file("s"), "--seed", "7", "--hours", "0.1"}).exit_code, 0);
  const auto r = run_sinu({"calibrate", "--in", tmp.file("s"), "--out", tmp.file("c.json"), "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json c = read_json(tmp.file("c.json"));
  EXPECT_FALSE(c.contains("six_position"));
  EXPECT_EQ(c["axes"]["ax"]["samples"], c["sessions"][0]["rows"]) << "every row";
  EXPECT_EQ(r.out.find("six-position"), std::string::npos) << r.out;
}

TEST_F(PositionsSession, ReplayRefusesAMalformedSectionNamingTheKey) {
  ASSERT_EQ(cal_->exit_code, 0) << cal_->err;
  json c = read_json(dir_->file("calib.json"));
  c["six_position"]["accel_scale"] = json::array({1.0, 2.0});
  const std::string bad = dir_->write("bad.json", c.dump());
  TempDir tmp;
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", tmp.file("f"), "--seed", "3", "--duration", "300"}).exit_code, 0);
  const auto r = run_sinu({"replay", "--in", tmp.file("f"), "--calib", bad, "--out", tmp.file("r"), "--quiet"});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("six_position.accel_scale"), std::string::npos) << r.err;
}

}  // namespace
