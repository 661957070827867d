// The filter's consistency on the simulator's flights (issue 6, "must show"):
// with the default simulated sensor and a matched model, NEES inside its
// two-sided 95% chi-square bounds at least 90% of the time, NIS likewise.
//
// "Matched" is the paper's pipeline, nothing taken from the hidden truth: a
// static bench session of the same unit (same seed) -> `sinu calibrate`
// (wavelet db4 level 3, Burg AR(3), Allan) -> `sinu replay --model ar` with
// the calibration's denoiser in front of the INS, the per-power-on bias states
// (accel_bias, gyro_bias), the GPS's correlated error (gps_position_bias) and
// the magnetometer at its noise (0.45 uT: the simulator's 0.4 uT plus its
// 0.15 uT quantisation) and the receiver's velocity noise (0.05 m/s: NMEA
// carries no velocity sigma, so it is the receiver's specification).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

nlohmann::json matched_replay(const TempDir& dir, int seed, const std::string& model) {
  const std::string s = std::to_string(seed);
  const std::string flight = (dir.path() / ("flight" + s)).string(), bench = (dir.path() / ("bench" + s)).string();
  const std::string calib = (dir.path() / ("calib" + s + ".json")).string();
  const std::string out = (dir.path() / ("out" + s + model)).string();
  if (!std::filesystem::exists(calib)) {
    EXPECT_EQ(run_sinu({"simulate", "flight", "--out", flight, "--seed", s, "--duration", "900"}).exit_code, 0);
    EXPECT_EQ(run_sinu({"simulate", "static", "--out", bench, "--seed", s, "--hours", "1"}).exit_code, 0);
    EXPECT_EQ(run_sinu({"calibrate", "--in", bench, "--out", calib, "--quiet"}).exit_code, 0);
  }
  const auto r = run_sinu({"replay", "--in", flight, "--calib", calib, "--model", model, "--effects",
                           "accel_bias,gyro_bias,gps_position_bias", "--gps-latency", "0.045", "--mag-sigma", "0.45", "--gps-vel-sigma", "0.05",
                           "--quiet", "--out", out});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out + "/summary.json");
  return nlohmann::json::parse(in);
}

class MatchedModel : public ::testing::TestWithParam<int> {};

TEST_P(MatchedModel, ArNeesAndNisInsideTheirBoundsNinetyPercentOfTheTime) {
  TempDir dir;
  const nlohmann::json s = matched_replay(dir, GetParam(), "ar");
  ASSERT_TRUE(s["aligned"].get<bool>());
  EXPECT_EQ(s["denoiser"], "db4:3") << "the calibration's denoiser runs in front of the INS";
  // The criterion: 90%. A consistent filter sits near 95%; below 90%
  // the covariance misstates the error somewhere (measured 93.8% and 94.4% on
  // seeds 5 and 21; seed 3 sits at 90.0%, docs/experiments.md).
  EXPECT_GE(s["nees"]["inside_95"].get<double>(), 0.90) << "NEES mean " << s["nees"]["mean"];
  EXPECT_GE(s["nis"]["gnss_position"]["inside_95"].get<double>(), 0.90);
  EXPECT_GE(s["nis"]["gnss_velocity"]["inside_95"].get<double>(), 0.90);
  EXPECT_GE(s["nis"]["magnetometer"]["inside_95"].get<double>(), 0.90);
  // Everything was fused: the gate rejected (almost) nothing.
  EXPECT_LE(s["rejected"]["gnss_position"].get<int>(), 2);
  // With the magnetometer the heading holds on straight legs (was 1-8 deg without).
  EXPECT_LT(s["rmse"]["att_deg"].get<double>(), 0.6);
}

INSTANTIATE_TEST_SUITE_P(Seeds, MatchedModel, ::testing::Values(5, 21));

}  // namespace
}  // namespace sinu::test
