// sinu calibrate end to end: simulated static sessions (sinu simulate static,
// issue 3) in, calib.json and report out; hidden simulator values as truth;
// bad input gives clear errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace {

using nlohmann::json;
using sinu::test::run_sinu;
using sinu::test::TempDir;

json read_json(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

// One simulated 8-hour bench session (the paper's length), run once for the
// three checks below (one test, so ctest's per-test processes do not repeat
// the ~30 s of simulation and calibration). A shorter session was tried and
// does not prove the point: with 3 h the Allan curve ends at tau = 2700 s, and
// for a bias with a long correlation time (seed 4242, gy: 443 s, whose ADEV
// crest is near 1.9 x 443 = 840 s) too few clusters remain around the crest;
// B then read 0.65 of the hidden sigma, outside the factor 1.5.
class SimulatedSession : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    const auto sim = run_sinu({"simulate", "static", "--out", dir_->file("bench"), "--seed", "4242", "--hours", "8",
                               "--hidden-out", dir_->file("hidden.json")});
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    const auto cal = run_sinu({"calibrate", "--in", dir_->file("bench"), "--out", dir_->file("calib.json"), "--report",
                               dir_->file("report"), "--quiet"});
    ASSERT_EQ(cal.exit_code, 0) << cal.err;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static TempDir* dir_;
};
TempDir* SimulatedSession::dir_ = nullptr;

TEST_F(SimulatedSession, AllanTermsSchemaAndFindings) {
  const json calib = read_json(dir_->file("calib.json"));
  const json hidden = read_json(dir_->file("hidden.json"))["imu_error_model"];
  const char* axes[] = {"ax", "ay", "az", "gx", "gy", "gz"};
  for (int i = 0; i < 6; ++i) {
    const std::string ax = axes[i];
    const json& h = hidden[ax[0] == 'a' ? "accel" : "gyro"];
    const auto k = static_cast<std::size_t>(i % 3);
    const double n_true = h["white_noise_density"][k];
    const double gm_sigma = h["gm_sigma"][k];
    const json& allan = calib["axes"][ax]["allan"];
    // White-noise density within 10% (the bound; measured 1-5%).
    EXPECT_NEAR(allan["N"].get<double>(), n_true, 0.10 * n_true) << ax;
    // Bias instability within a factor 1.5 of the simulator's bias process:
    // a Gauss-Markov bias of std sigma reads B = 0.62 sigma / 0.664 = 0.93
    // sigma on the Allan plot, so sigma is the hidden value to compare with.
    const double ratio = allan["B"].get<double>() / gm_sigma;
    EXPECT_LT(ratio, 1.5) << ax;
    EXPECT_GT(ratio, 1.0 / 1.5) << ax;
  }
  // calib.json has the schema the EKF reads.
  EXPECT_EQ(calib["denoiser"]["wavelet"], "db4");
  EXPECT_EQ(calib["denoiser"]["levels"], 3);
  EXPECT_NEAR(calib["denoiser"]["sample_rate_hz"].get<double>(), 40.0, 1e-6);
  for (const char* ax : {"ax", "ay", "az", "gx", "gy", "gz"}) {
    const json& a = calib["axes"][ax];
    ASSERT_TRUE(a.contains("gm")) << ax;
    EXPECT_GT(a["gm"]["variance"].get<double>(), 0.0);
    EXPECT_TRUE(a["gm"].contains("tau_s"));
    for (const char* m : {"yule_walker", "covariance", "burg"}) {
      const json& list = a["ar"][m];
      ASSERT_EQ(list.size(), 10u) << ax << " " << m;
      for (std::size_t p = 1; p <= 10; ++p) {
        ASSERT_EQ(list[p - 1]["a"].size(), p + 1);
        EXPECT_EQ(list[p - 1]["a"][0], 1.0);
        EXPECT_GT(list[p - 1]["variance"].get<double>(), 0.0);
      }
    }
    EXPECT_EQ(a["allan"]["tau_s"].size(), a["allan"]["adev"].size());
    for (const char* t : {"N", "B", "K"}) EXPECT_TRUE(a["allan"].contains(t));
    EXPECT_EQ(a["model"]["method"], "burg");
    EXPECT_EQ(a["model"]["order"], 3);
    EXPECT_EQ(a["model"]["a"], a["ar"]["burg"][2]["a"]);
    EXPECT_TRUE(a.contains("turn_on_bias"));
  }
  // The turn-on bias is the mean: az of a level bench is about -g.
  EXPECT_NEAR(calib["axes"]["az"]["turn_on_bias"].get<double>(), -9.8, 0.3);
  EXPECT_EQ(calib["sessions"].size(), 1u);

  // The simulator adds a periodic-random component (a damped resonator) on
  // every axis: the report must name it as what GM1 misses.
  std::ifstream in(dir_->file("report") + "/report.md");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("GM1 misses the periodic component near"), std::string::npos) << text;
  for (const char* f : {"ar_variance.csv", "ar_coefficients.csv", "gm_vs_ar.csv", "acf_s1_ax.csv", "allan_s1_gz.csv"}) {
    EXPECT_TRUE(std::ifstream(dir_->file("report") + "/" + f).good()) << f;
  }
}

// The denoiser's thresholds: the noise in each level's details, so that a
// flight keeps what is beyond it (fast motion) and drops the rest.
TEST_F(SimulatedSession, DetailSigmasAreTheWhiteNoiseAndAReplayUsesThem) {
  const json calib = read_json(dir_->file("calib.json"));
  const json& d = calib["denoiser"];
  EXPECT_EQ(d["keep_details_above_sigma"].get<double>(), 4.0);
  const json hidden = read_json(dir_->file("hidden.json"))["imu_error_model"];
  const char* axes[] = {"ax", "ay", "az", "gx", "gy", "gz"};
  for (int i = 0; i < 6; ++i) {
    const json& h = hidden[axes[i][0] == 'a' ? "accel" : "gyro"];
    // White noise of density N at 40 Hz is N sqrt(40) per sample, and an
    // orthonormal wavelet's details carry that sigma at every level. The
    // finest level sees the white noise alone: within 10 % (the median's
    // sampling error over 576000 details is 0.2 %; the simulator's
    // correlated terms live below 1 Hz). Coarser levels may add the
    // resonator: at least 0.9x.
    const double white = h["white_noise_density"][static_cast<std::size_t>(i % 3)].get<double>() * std::sqrt(40.0);
    const json& sigma = d["detail_sigma"][axes[i]];
    ASSERT_EQ(sigma.size(), 3u) << axes[i];
    EXPECT_NEAR(sigma[0].get<double>(), white, 0.10 * white) << axes[i];
    for (const json& s : sigma) EXPECT_GT(s.get<double>(), 0.9 * white) << axes[i];
  }
  // A calib.json whose thresholds are malformed is refused, naming the key.
  json bad = calib;
  bad["denoiser"]["detail_sigma"]["gz"] = json::array({0.001, 0.001});
  std::ofstream(dir_->file("bad_calib.json")) << bad.dump();
  const auto sim = run_sinu({"simulate", "flight", "--out", dir_->file("short"), "--seed", "7", "--duration", "300"});
  ASSERT_EQ(sim.exit_code, 0);
  const auto rep = run_sinu({"replay", "--in", dir_->file("short"), "--calib", dir_->file("bad_calib.json"), "--quiet",
                             "--out", dir_->file("replay_bad")});
  EXPECT_EQ(rep.exit_code, 1);
  EXPECT_NE(rep.err.find("denoiser.detail_sigma.gz"), std::string::npos) << rep.err;
  const auto ok = run_sinu({"replay", "--in", dir_->file("short"), "--calib", dir_->file("calib.json"), "--quiet",
                            "--out", dir_->file("replay_ok")});
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(read_json(dir_->file("replay_ok") + "/summary.json")["denoiser"].get<std::string>().find("4 sigma"),
            std::string::npos);
}

// Issue 14: the AR models also at the rate whose Allan deviation fits the
// measured one best over 1-100 s (the span of an outage), and the EKF uses them.
TEST_F(SimulatedSession, ArModelsAtTheRateThatFitsTheAllanDeviationAndTheReplayUsesThem) {
  const json calib = read_json(dir_->file("calib.json"));
  ASSERT_TRUE(calib.contains("ar_model_rate"));
  const json& r = calib["ar_model_rate"];
  // The IMU rate is one of the candidates, and the chosen rate scores best.
  bool imu_rate_tried = false;
  double best = 1e300;
  for (const json& c : r["candidates"]) {
    if (std::abs(c["rate_hz"].get<double>() - 40.0) < 1e-9) imu_rate_tried = true;
    if (!c["score"].is_null()) best = std::min(best, c["score"].get<double>());
  }
  EXPECT_TRUE(imu_rate_tried);
  double chosen = -1.0;
  for (const json& c : r["candidates"])
    if (c["rate_hz"] == r["rate_hz"]) chosen = c["score"].get<double>();
  EXPECT_EQ(chosen, best);
  // A slower model than the IMU rate wins, and clearly: measured 0.5 Hz, score
  // 0.30 against 0.42 at 40 Hz (RMS of ln(model/measured): 35 % against 52 %
  // typical misfit). 0.8x separates a real gain from a tie.
  double imu_score = 1e300;
  for (const json& c : r["candidates"])
    if (std::abs(c["rate_hz"].get<double>() - 40.0) < 1e-9) imu_score = c["score"].get<double>();
  EXPECT_LT(r["rate_hz"].get<double>(), 40.0);
  EXPECT_LT(chosen, 0.8 * imu_score);
  // Where an outage lives (5-50 s), the model-rate AR(3) stays within a
  // factor 2.2 of the measured Allan deviation on every axis (measured
  // 0.94-2.03: the simulator's periodic component makes a bump no AR(3) at one
  // rate follows everywhere), where the 40-Hz AR(3), describing the denoiser's
  // band, falls to 0.35-0.5x on some axis (the slow error it forgets).
  double worst_imu = 1.0;
  for (const char* ax : {"ax", "ay", "az", "gx", "gy", "gz"}) {
    const json& a = r["axes"][ax]["adev"];
    for (std::size_t k = 0; k < a["tau_s"].size(); ++k) {
      const double tau = a["tau_s"][k].get<double>();
      if (tau < 5.0 || tau > 50.0) continue;
      const double measured = a["measured"][k].get<double>();
      const double ratio = a["ar_model_rate"][k].get<double>() / measured;
      EXPECT_LT(ratio, 2.2) << ax << " tau " << tau;
      EXPECT_GT(ratio, 1.0 / 2.2) << ax << " tau " << tau;
      worst_imu = std::min(worst_imu, a["ar_imu_rate"][k].get<double>() / measured);
    }
    ASSERT_EQ(r["axes"][ax]["ar"]["burg"].size(), 10u);
  }
  EXPECT_LT(worst_imu, 1.0 / 2.2) << "the 40-Hz AR(3) underestimates the slow error somewhere";
  // replay takes the model-rate AR by default (its states step at that rate), the IMU rate's when asked.
  const auto sim = run_sinu({"simulate", "flight", "--out", dir_->file("flight"), "--seed", "4242", "--duration", "300"});
  ASSERT_EQ(sim.exit_code, 0);
  for (const auto& [rate, expect_hz] : {std::pair<std::string, double>{"model", r["rate_hz"].get<double>()},
                                        std::pair<std::string, double>{"imu", 40.0}}) {
    const auto rep = run_sinu({"replay", "--in", dir_->file("flight"), "--calib", dir_->file("calib.json"), "--ar-rate",
                               rate, "--quiet", "--out", dir_->file("replay_" + rate)});
    ASSERT_EQ(rep.exit_code, 0) << rep.err;
    EXPECT_NEAR(read_json(dir_->file("replay_" + rate) + "/summary.json")["ar"]["rate_hz"].get<double>(), expect_hz,
                1e-9)
        << rate;
  }
}

TEST(CalibrateCli, MissingDatasetIsRuntimeErrorNamingTheFile) {
  TempDir dir;
  const auto r = run_sinu({"calibrate", "--in", dir.file("nope"), "--out", dir.file("c.json"), "--no-denoise"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("imu.csv"), std::string::npos) << r.err;
}

TEST(CalibrateCli, MalformedRowNamesLineAndField) {
  TempDir dir;
  std::string csv = "t,ax,ay,az,gx,gy,gz,mx,my,mz,temp\n";
  for (int i = 0; i < 1500; ++i) {
    csv += std::to_string(100.0 + 0.025 * i) + ",0.01,0.02,-9.8,0.001,0.002,0.003,20,0,40,25\n";
  }
  csv += "137.5,0.01,abc,-9.8,0.001,0.002,0.003,20,0,40,25\n";
  std::filesystem::create_directories(dir.path() / "bad");
  dir.write("bad/imu.csv", csv);
  const auto r = run_sinu({"calibrate", "--in", dir.file("bad"), "--out", dir.file("c.json"), "--no-denoise"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(":1502:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ay"), std::string::npos) << r.err;
}

TEST(CalibrateCli, TooShortSessionAndBadOptionsAreRefused) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "short");
  dir.write("short/imu.csv", "t,ax,ay,az,gx,gy,gz,mx,my,mz,temp\n1,0,0,-9.8,0,0,0,,,,\n");
  auto r = run_sinu({"calibrate", "--in", dir.file("short"), "--out", dir.file("c.json"), "--no-denoise"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("at least"), std::string::npos) << r.err;
  r = run_sinu({"calibrate", "--in", dir.file("short"), "--out", dir.file("c.json"), "--model", "burg:11"});
  EXPECT_EQ(r.exit_code, 2);
  r = run_sinu({"calibrate", "--in", dir.file("short"), "--out", dir.file("c.json"), "--wavelet", "sym8"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("sym8"), std::string::npos) << r.err;
  r = run_sinu({"calibrate", "--out", dir.file("c.json")});
  EXPECT_EQ(r.exit_code, 2);
}

// A flight given to calibrate by mistake (the folder names look alike): its
// turns and climbs were fitted as sensor noise, and calib.json claimed a
// unit hundreds of times noisier than it is, silently. Now it is refused,
// naming the axis and its span; the bench session of the same seed passes.
TEST(CalibrateCli, AFlightIsRefusedAsABenchSession) {
  TempDir dir;
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", dir.file("flight"), "--seed", "4", "--duration", "600"}).exit_code,
            0);
  auto r = run_sinu({"calibrate", "--in", dir.file("flight"), "--out", dir.file("c.json"), "--quiet"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("the unit moved; calibrate needs a bench session held still"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(dir.file("flight")), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("c.json")));
  ASSERT_EQ(run_sinu({"simulate", "static", "--out", dir.file("bench"), "--seed", "4", "--duration", "600"}).exit_code,
            0);
  r = run_sinu({"calibrate", "--in", dir.file("bench"), "--out", dir.file("c.json"), "--quiet"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// A bench session that warms up: its accelerometer x drifts by 0.3 m/s^2 over
// the hour (the independent simulator's bench warmed 18 degC with a 0.012
// m/s^2/degC coefficient). Its autocorrelation never falls to 1/e, and sinu
// calibrate wrote gm.tau_s null ("decays": false): every command with --model
// gm, diagnose's default, refused calib.json while replay's AR read it. A
// calibration sinu writes must be read by every model.
TEST(CalibrateCli, ABenchThatDriftsGivesACalibrationEveryModelReads) {
  TempDir dir;
  ASSERT_EQ(run_sinu({"simulate", "static", "--out", dir.file("bench"), "--seed", "3", "--hours", "1"}).exit_code, 0);
  {
    std::ifstream in(dir.file("bench") + "/imu.csv");
    std::string line, out;
    std::getline(in, line);
    out = line + "\n";
    double t0 = NAN;
    while (std::getline(in, line)) {
      const std::size_t c1 = line.find(','), c2 = line.find(',', c1 + 1);
      const double t = std::stod(line.substr(0, c1)), ax = std::stod(line.substr(c1 + 1, c2 - c1 - 1));
      if (std::isnan(t0)) t0 = t;
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.9g", ax + 0.3 * (t - t0) / 3600.0);
      out += line.substr(0, c1 + 1) + buf + line.substr(c2) + "\n";
    }
    in.close();
    std::ofstream(dir.file("bench") + "/imu.csv") << out;
  }
  const auto cal = run_sinu({"calibrate", "--in", dir.file("bench"), "--out", dir.file("calib.json"), "--quiet"});
  ASSERT_EQ(cal.exit_code, 0) << cal.err;
  ASSERT_FALSE(read_json(dir.file("calib.json"))["axes"]["ax"]["gm"]["decays"].get<bool>())
      << "the drift must defeat the 1/e crossing, or this test tests nothing";
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", dir.file("flight"), "--seed", "3", "--duration", "300"}).exit_code,
            0);
  for (const char* model : {"gm", "ar"}) {
    const std::string out = dir.file(std::string("replay_") + model);
    const auto r = run_sinu({"replay", "--in", dir.file("flight"), "--calib", dir.file("calib.json"), "--model", model,
                             "--quiet", "--out", out});
    ASSERT_EQ(r.exit_code, 0) << model << ": " << r.err;
    const json s = read_json(out + "/summary.json");
    EXPECT_TRUE(s["aligned"].get<bool>()) << model;
    EXPECT_EQ(s["health"]["status"], "ok") << model;
  }
  const auto d = run_sinu({"diagnose", "--in", dir.file("flight"), "--calib", dir.file("calib.json"), "--rounds", "1",
                           "--quiet", "--out", dir.file("diag")});
  EXPECT_EQ(d.exit_code, 0) << d.err;
}

}  // namespace
