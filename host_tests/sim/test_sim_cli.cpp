// sinu simulate on the command line: determinism, options, the hidden file,
// and clear errors for bad effects files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "firmware/host/sim/effects.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

using sinu::test::run_sinu;
using sinu::test::read_file;
using sinu::test::TempDir;

namespace {

}  // namespace

TEST(SimulateCli, SameSeedSameBytesOtherSeedOtherData) {
  TempDir tmp;
  const std::vector<std::string> common = {"--duration", "300", "--effects-random", "3"};
  auto args = [&](const std::string& dir, const std::string& seed) {
    std::vector<std::string> a = {"simulate", "flight", "--out", tmp.file(dir), "--seed", seed,
                                  "--hidden-out", tmp.file(dir + ".json")};
    a.insert(a.end(), common.begin(), common.end());
    return a;
  };
  ASSERT_EQ(run_sinu(args("a", "17")).exit_code, 0);
  ASSERT_EQ(run_sinu(args("b", "17")).exit_code, 0);
  ASSERT_EQ(run_sinu(args("c", "18")).exit_code, 0);
  for (const char* f : {"imu.csv", "gps.nmea", "truth.csv", "meta.json"}) {
    EXPECT_EQ(read_file(tmp.file(std::string("a/") + f)), read_file(tmp.file(std::string("b/") + f))) << f;
    EXPECT_NE(read_file(tmp.file(std::string("a/") + f)), read_file(tmp.file(std::string("c/") + f))) << f;
  }
  EXPECT_EQ(read_file(tmp.file("a.json")), read_file(tmp.file("b.json")));
  // The hidden file holds the three effects; the dataset folder holds only
  // the four files of the format.
  const auto hidden = nlohmann::json::parse(read_file(tmp.file("a.json")));
  EXPECT_EQ(hidden["effects"].size(), 3u);
  EXPECT_EQ(hidden["schema"], "sinu-simulate-hidden/1");
  std::set<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(tmp.file("a"))) files.insert(e.path().filename().string());
  EXPECT_EQ(files, (std::set<std::string>{"imu.csv", "gps.nmea", "truth.csv", "meta.json"}));
}

TEST(SimulateCli, HiddenEffectsFedBackReproduceTheDataset) {
  TempDir tmp;
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", tmp.file("a"), "--seed", "5", "--duration", "300",
                      "--effects-random", "4", "--hidden-out", tmp.file("a.json")})
                .exit_code,
            0);
  const auto hidden = nlohmann::json::parse(read_file(tmp.file("a.json")));
  const std::string fx = tmp.write("fx.json", hidden["effects"].dump());
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", tmp.file("b"), "--seed", "5", "--duration", "300", "--effects",
                      fx})
                .exit_code,
            0);
  EXPECT_EQ(read_file(tmp.file("a/imu.csv")), read_file(tmp.file("b/imu.csv")));
  EXPECT_EQ(read_file(tmp.file("a/gps.nmea")), read_file(tmp.file("b/gps.nmea")));
}

TEST(SimulateCli, RatesAndDurationAreHonoured) {
  TempDir tmp;
  const auto r = run_sinu({"simulate", "flight", "--out", tmp.file("d"), "--seed", "2", "--duration", "360",
                           "--imu-rate", "100", "--gps-rate", "10"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto meta = nlohmann::json::parse(read_file(tmp.file("d/meta.json")));
  EXPECT_EQ(meta["imu_rate_hz"], 100.0);
  EXPECT_EQ(meta["gps_rate_hz"], 10.0);
  const auto insp = run_sinu({"inspect", "dataset", tmp.file("d")});
  ASSERT_EQ(insp.exit_code, 0) << insp.err;
  EXPECT_NE(insp.out.find("36000 rows"), std::string::npos) << insp.out;
  EXPECT_NE(insp.out.find("100.00 Hz"), std::string::npos) << insp.out;
  EXPECT_NE(insp.out.find("10.00 Hz"), std::string::npos) << insp.out;
}

TEST(SimulateCli, UsageErrorsExitTwo) {
  TempDir tmp;
  const std::string out = tmp.file("o");
  EXPECT_EQ(run_sinu({"simulate", "flight", "--seed", "1"}).exit_code, 2);  // --out missing
  EXPECT_EQ(run_sinu({"simulate", "flight", "--out", out}).exit_code, 2);   // --seed missing
  EXPECT_EQ(run_sinu({"simulate", "flight", "--out", out, "--seed", "1", "--effects", "x.json", "--effects-random",
                      "2"})
                .exit_code,
            2);
  EXPECT_EQ(run_sinu({"simulate", "flight", "--out", out, "--seed", "1", "--effects-random", "12"}).exit_code, 2);
  EXPECT_EQ(run_sinu({"simulate", "flight", "--out", out, "--seed", "1", "--imu-rate", "0"}).exit_code, 2);
  EXPECT_EQ(run_sinu({"simulate", "flight", "--out", out, "--seed", "1", "--duration", "10"}).exit_code, 2);
  EXPECT_EQ(run_sinu({"simulate", "static", "--out", out, "--seed", "1", "--duration", "5", "--hours", "1"}).exit_code,
            2);
  const auto inside = run_sinu({"simulate", "static", "--out", out, "--seed", "1", "--duration", "10",
                                "--hidden-out", out + "/truth.json"});
  EXPECT_EQ(inside.exit_code, 2);
  EXPECT_NE(inside.err.find("inside the dataset folder"), std::string::npos) << inside.err;
}

TEST(SimulateCli, BadEffectsFileNamesFileAndKey) {
  TempDir tmp;
  struct Case {
    const char* json;
    const char* key;  // must appear in the message
  };
  const Case cases[] = {
      {R"({"lever_arm": [0.6, -0.2, -0.4], "wind": 3})", "'wind'"},
      {R"({"lever_arm": [0.6, -0.2]})", "'lever_arm'"},
      {R"({"gps_latency": "0.1"})", "'gps_latency'"},
      {R"({"gps_latency": -0.1})", "'gps_latency'"},
      {R"({"accel_scale": [1, 2, "NaN"]})", "'accel_scale'"},
      {R"({"gyro_misalign": [[0.01, 0, 0], [0, 0, 0], [0, 0, 0]]})", "'gyro_misalign'"},
      {R"({"mag_soft_iron": [1, 0, 0]})", "'mag_soft_iron'"},
      {R"({"lever_arm": [0.6, NaN, 1]})", "not valid JSON"},
      {R"([1, 2])", "top level"},
  };
  int i = 0;
  for (const Case& c : cases) {
    const std::string f = tmp.write("fx" + std::to_string(i++) + ".json", c.json);
    const auto r = run_sinu({"simulate", "flight", "--out", tmp.file("o"), "--seed", "1", "--duration", "300",
                             "--effects", f});
    EXPECT_EQ(r.exit_code, 2) << c.json;
    EXPECT_NE(r.err.find(f), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.key), std::string::npos) << r.err;
  }
  const auto missing = run_sinu({"simulate", "flight", "--out", tmp.file("o"), "--seed", "1", "--effects",
                                 tmp.file("nope.json")});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("nope.json"), std::string::npos);
}

TEST(SimulateCli, UnwritableOutputExitsOne) {
  TempDir tmp;
  const std::string file = tmp.write("plain", "x");
  const auto r = run_sinu({"simulate", "static", "--out", file + "/sub", "--seed", "1", "--duration", "10"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("plain"), std::string::npos) << r.err;
}

TEST(SimulateEffects, JsonRoundTripAndRandomDrawsAreDistinct) {
  sinu::sim::Rng rng(9, sinu::sim::RngStream::Effects);
  const auto fx = sinu::sim::draw_random_effects(11, rng);
  EXPECT_EQ(fx.count(), 11u);
  sinu::sim::Effects back;
  sinu::dataset::Diagnostic err;
  ASSERT_TRUE(sinu::sim::parse_effects(sinu::sim::effects_to_json(fx), "mem", back, err)) << err.to_string();
  EXPECT_EQ(sinu::sim::effects_to_json(back), sinu::sim::effects_to_json(fx));
  for (std::size_t k = 0; k <= 11; ++k) {
    sinu::sim::Rng r(k, sinu::sim::RngStream::Effects);
    EXPECT_EQ(sinu::sim::draw_random_effects(k, r).count(), k);
  }
}
