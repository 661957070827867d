// sinu bench: a static session recorded through the drivers (here the
// emulated board playing a simulated bench session), calibrated, and its
// calib.json put where sinu fly reads it; a session in which the board is
// tilted or the temperature steps is warned about and marked at the right
// times.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "host_tests/support/read_json.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

/// A simulated static session as the chip's registers give it.
std::string bench_session(const TempDir& tmp, int seconds) {
  const std::string dir = tmp.file("static"), raw = tmp.file("static.raw"), q = tmp.file("static_q");
  EXPECT_EQ(run_sinu({"simulate", "static", "--duration", std::to_string(seconds), "--seed", "4", "--out", dir}).exit_code, 0);
  EXPECT_EQ(run_sinu({"convert", dir, raw}).exit_code, 0);
  EXPECT_EQ(run_sinu({"convert", raw, q}).exit_code, 0);
  return q;
}

TEST(Bench, AStillSessionIsCalibratedAndItsCalibJsonGoesWhereFlyReadsIt) {
  TempDir tmp;
  const std::string session = bench_session(tmp, 1200);
  const std::string out = tmp.file("bench"), target = tmp.file("var_lib_sinu/calib.json");
  const ProcessResult r = run_sinu({"bench", "--emulate", session, "--speed", "0", "--hours", "0.25", "--out", out,
                                    "--calib", target, "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json b = read_json(out + "/bench.json");
  EXPECT_TRUE(b["still"].get<bool>()) << b.dump();
  EXPECT_NEAR(b["imu_samples"].get<double>(), 900.0 * 40.0, 40.0) << "a quarter of an hour at 40 Hz";
  EXPECT_EQ(read_file(target), read_file(out + "/calib.json"));
  const nlohmann::json calib = read_json(target);
  EXPECT_TRUE(calib.contains("axes")) << "a calib.json sinu fly and sinu replay read";
  EXPECT_EQ(r.err.find("WARNING"), std::string::npos) << r.err;
}

// imu.csv rewritten: from `tilt_t` on the board stands 2 deg tilted about x;
// from `temp_t` on the die is 2 degC warmer.
std::string disturbed(const TempDir& tmp, const std::string& session, double tilt_t, double temp_t) {
  const std::string dir = tmp.file("disturbed");
  std::filesystem::create_directories(dir);
  std::ifstream in(session + "/imu.csv");
  std::ofstream out(dir + "/imu.csv");
  std::string line;
  std::getline(in, line);
  out << line << "\n";
  const double c = std::cos(2.0 * M_PI / 180.0), s = std::sin(2.0 * M_PI / 180.0);
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    if (line.back() == ',') f.emplace_back();
    const double t = std::stod(f[0]);
    if (t >= tilt_t) {
      const double ay = std::stod(f[2]), az = std::stod(f[3]);
      f[2] = std::to_string(c * ay - s * az);
      f[3] = std::to_string(s * ay + c * az);
    }
    if (t >= temp_t && !f[10].empty()) f[10] = std::to_string(std::stod(f[10]) + 2.0);
    for (std::size_t i = 0; i < f.size(); ++i) out << (i ? "," : "") << f[i];
    out << "\n";
  }
  return dir;
}

TEST(Bench, ATiltAndATemperatureStepAreWarnedAndMarkedWhenTheyHappen) {
  TempDir tmp;
  const std::string session = bench_session(tmp, 1200);
  std::ifstream in(session + "/imu.csv");
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  const double t0 = std::stod(line.substr(0, line.find(',')));
  const std::string dir = disturbed(tmp, session, t0 + 300.0, t0 + 600.0);
  const std::string out = tmp.file("bench");
  const ProcessResult r = run_sinu({"bench", "--emulate", dir, "--speed", "0", "--hours", "0.25", "--out", out, "--calib",
                                    tmp.file("calib.json"), "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;  // the calibration still runs: the user decides
  EXPECT_NE(r.err.find("not still"), std::string::npos) << r.err;
  const nlohmann::json b = read_json(out + "/bench.json");
  EXPECT_FALSE(b["still"].get<bool>());
  bool moved = false, stepped = false;
  for (const auto& m : b["marks"]) {
    const double start = m["start_t"].get<double>();
    if (m["event"] == "moved") {
      moved = true;
      EXPECT_NEAR(start, t0 + 300.0, 1.5) << "the 1-s window holding the tilt";
      // 2 deg, plus what the bias processes moved the mean since the reference (~0.2 deg).
      EXPECT_NEAR(m["size"].get<double>(), 2.0, 0.3) << "2 deg of tilt";
    }
    if (m["event"] == "temperature_step") {
      stepped = true;
      EXPECT_LE(start, t0 + 600.0);
      EXPECT_GE(m["end_t"].get<double>(), t0 + 600.0);
      EXPECT_NEAR(m["size"].get<double>(), 2.0, 0.6) << "the step, as seen on 10-s means";
    }
  }
  EXPECT_TRUE(moved) << b.dump();
  EXPECT_TRUE(stepped) << b.dump();
}

// --positions 6: the board asked for each face in turn (prompts on stderr),
// here an emulated board playing a session that holds the six faces a minute
// each; every face is held 30 s, then the whole recording is calibrated as a
// multi-position session.
TEST(Bench, SixPositionsAskedForHeldAndCalibrated) {
  TempDir tmp;
  const std::string dir = tmp.file("faces"), raw = tmp.file("faces.raw"), q = tmp.file("faces_q");
  ASSERT_EQ(run_sinu({"simulate", "static", "--positions", "6", "--hold-s", "60", "--seed", "4", "--out", dir})
                .exit_code,
            0);
  ASSERT_EQ(run_sinu({"convert", dir, raw}).exit_code, 0);
  ASSERT_EQ(run_sinu({"convert", raw, q}).exit_code, 0);
  const std::string out = tmp.file("bench"), target = tmp.file("var_lib_sinu/calib.json");
  const ProcessResult r = run_sinu({"bench", "--emulate", q, "--speed", "0", "--positions", "6", "--hold-s", "30",
                                    "--out", out, "--calib", target, "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const char* faces[] = {"-z up: level", "+x up: nose up", "+y up: on its left side", "-x up: nose down",
                         "-y up: on its right side", "+z up: upside down"};
  std::size_t at = 0;
  for (int k = 0; k < 6; ++k) {
    const std::string ask = "position " + std::to_string(k + 1) + "/6: place the board " + faces[k];
    const std::size_t p = r.err.find(ask, at);
    ASSERT_NE(p, std::string::npos) << ask << "\n" << r.err;
    const std::size_t held = r.err.find("position " + std::to_string(k + 1) + "/6 held", p);
    ASSERT_NE(held, std::string::npos) << r.err;
    at = held;
  }
  const nlohmann::json b = read_json(out + "/bench.json");
  ASSERT_EQ(b["held"].size(), 6u) << b.dump();
  for (const auto& f : b["held"]) {
    EXPECT_EQ(f["asked"], f["held"]);
    EXPECT_NEAR(f["end_t"].get<double>() - f["start_t"].get<double>(), 30.0, 1.0) << "held 30 s (1-s windows)";
  }
  const nlohmann::json calib = read_json(target);
  ASSERT_TRUE(calib.contains("six_position")) << calib.dump().substr(0, 200);
  EXPECT_EQ(calib["six_position"]["segments_used"], 6);
  EXPECT_EQ(calib["six_position"]["attitudes"], 6);
  EXPECT_TRUE(calib.contains("axes"));
  EXPECT_NE(r.out.find("six-position: 6 still segments"), std::string::npos) << r.out;
}

// A recording that ends before every position was held calibrates nothing.
TEST(Bench, PositionsNotAllHeldIsAFailure) {
  TempDir tmp;
  const std::string session = bench_session(tmp, 120);  // level only
  const ProcessResult r = run_sinu({"bench", "--emulate", session, "--speed", "0", "--positions", "6", "--hold-s",
                                    "30", "--out", tmp.file("bench"), "--calib", tmp.file("calib.json"), "--quiet"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("1 of 6 positions held"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("calib.json")));
}

}  // namespace
}  // namespace sinu::test
