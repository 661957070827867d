// sinu simulate on the command line: determinism, options, the hidden file,
// and clear errors for bad effects files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "firmware/host/sim/effects.hpp"
#include "firmware/host/sim/effects/effect_list.hpp"
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

// --site puts the flight where the seed would not (|lat| < 60 by default): the
// hidden truth, the first truth row and the first GGA say the same place; the
// rest of the seed's draw is unchanged (same IMU row count, same clock start).
TEST(SimulateCli, SiteOptionPlacesTheFlight) {
  TempDir tmp;
  const auto r = run_sinu({"simulate", "flight", "--out", tmp.file("d"), "--seed", "2", "--duration", "300",
                           "--site", "78.2,15.6,40", "--hidden-out", tmp.file("h.json")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto hidden = nlohmann::json::parse(read_file(tmp.file("h.json")));
  EXPECT_DOUBLE_EQ(hidden["site"]["lat_deg"].get<double>(), 78.2);
  EXPECT_DOUBLE_EQ(hidden["site"]["lon_deg"].get<double>(), 15.6);
  EXPECT_DOUBLE_EQ(hidden["site"]["ground_h_m"].get<double>(), 40.0);
  const std::string truth = read_file(tmp.file("d/truth.csv"));
  const std::string first_row = truth.substr(truth.find('\n') + 1, 60);
  EXPECT_NE(first_row.find(",78.2000000"), std::string::npos) << first_row;
  EXPECT_NE(read_file(tmp.file("d/gps.nmea")).find(",7812.0000"), std::string::npos);  // 78.2 deg = 78 deg 12'
  const auto drawn = run_sinu({"simulate", "flight", "--out", tmp.file("e"), "--seed", "2", "--duration", "300"});
  ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
  const std::string drawn_truth = read_file(tmp.file("e/truth.csv"));
  EXPECT_EQ(drawn_truth.substr(0, drawn_truth.find(',', drawn_truth.find('\n'))),
            truth.substr(0, truth.find(',', truth.find('\n'))))
      << "the board clock's start is the seed's";
  for (const char* bad : {"91,0,0", "0,181,0", "0,0,20000", "84,1"}) {
    const auto u = run_sinu({"simulate", "flight", "--out", tmp.file("f"), "--seed", "2", "--site", bad});
    EXPECT_EQ(u.exit_code, 2) << bad;
    EXPECT_NE(u.err.find("--site"), std::string::npos) << bad << ": " << u.err;
  }
}

TEST(SimulateCli, TheAirframeIsSaidInMetaAndHidden) {
  TempDir tmp;
  const auto r = run_sinu({"simulate", "flight", "--out", tmp.file("d"), "--seed", "2", "--duration", "300",
                           "--airframe", "multirotor", "--hidden-out", tmp.file("h.json")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(read_file(tmp.file("h.json")))["airframe"], "multirotor");
  EXPECT_NE(read_file(tmp.file("d/meta.json")).find("--airframe multirotor"), std::string::npos);
  // The same seed as a fixed wing (the default) flies elsewhere.
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", tmp.file("e"), "--seed", "2", "--duration", "300"}).exit_code, 0);
  EXPECT_NE(read_file(tmp.file("d/truth.csv")), read_file(tmp.file("e/truth.csv")));
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
  // One more random effect than the vocabulary has.
  const std::string too_many = std::to_string(sinu::sim::kEffectNames.size() + 1);
  EXPECT_EQ(run_sinu({"simulate", "flight", "--out", out, "--seed", "1", "--effects-random", too_many}).exit_code, 2);
  EXPECT_EQ(run_sinu({"simulate", "flight", "--out", out, "--seed", "1", "--imu-rate", "0"}).exit_code, 2);
  EXPECT_EQ(run_sinu({"simulate", "flight", "--out", out, "--seed", "1", "--duration", "10"}).exit_code, 2);
  const auto heli = run_sinu({"simulate", "flight", "--out", out, "--seed", "1", "--airframe", "helicopter"});
  EXPECT_EQ(heli.exit_code, 2);
  EXPECT_NE(heli.err.find("--airframe"), std::string::npos) << heli.err;
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

// A multi-position bench session: the same seed gives the same bytes; the
// hidden file says where each position was held and the unit's drawn
// accelerometer scale and misalignment, which a flight of the same seed
// with --unit-accel-errors has too (one unit); without it a flight (and a
// level session) is as before: no such effects.
TEST(SimulateCli, PositionsSessionAndTheUnitsAccelErrors) {
  TempDir tmp;
  auto positions = [&](const std::string& dir) {
    return run_sinu({"simulate", "static", "--out", tmp.file(dir), "--seed", "12", "--positions", "7", "--hold-s",
                     "30", "--transition-s", "3", "--hidden-out", tmp.file(dir + ".json")});
  };
  const auto r = positions("a");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("2 effect(s)"), std::string::npos) << r.out;
  ASSERT_EQ(positions("b").exit_code, 0);
  EXPECT_EQ(read_file(tmp.file("a/imu.csv")), read_file(tmp.file("b/imu.csv")));
  EXPECT_EQ(read_file(tmp.file("a.json")), read_file(tmp.file("b.json")));
  const auto h = nlohmann::json::parse(read_file(tmp.file("a.json")));
  ASSERT_EQ(h["positions"].size(), 7u);
  EXPECT_EQ(h["positions"][0]["name"], "-z up");
  EXPECT_EQ(h["positions"][6]["name"], "+x+y+z up");
  // 7 holds of 30 s and 6 turns of 3 s.
  EXPECT_DOUBLE_EQ(h["duration_s"].get<double>(), 7 * 30.0 + 6 * 3.0);
  const double t0 = h["t0_s"];
  EXPECT_DOUBLE_EQ(h["positions"][1]["still_from_t"].get<double>() - t0, 33.0);
  for (const auto& p : h["positions"]) {
    // The true specific force of a held position is gravity: 9.78..9.84 m/s^2 anywhere on Earth.
    const auto& f = p["true_specific_force_b_m_s2"];
    const double g = std::hypot(f[0].get<double>(), f[1].get<double>(), f[2].get<double>());
    EXPECT_GT(g, 9.77);
    EXPECT_LT(g, 9.84);
  }
  ASSERT_TRUE(h["effects"].contains("accel_scale"));
  ASSERT_TRUE(h["effects"].contains("accel_misalign"));
  for (const auto& s : h["effects"]["accel_scale"]) EXPECT_LE(std::abs(s.get<double>()), 15000.0);

  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", tmp.file("f"), "--seed", "12", "--duration", "300",
                      "--unit-accel-errors", "--hidden-out", tmp.file("f.json")})
                .exit_code,
            0);
  EXPECT_EQ(nlohmann::json::parse(read_file(tmp.file("f.json")))["effects"], h["effects"]) << "one unit, one seed";
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", tmp.file("g"), "--seed", "12", "--duration", "300",
                      "--hidden-out", tmp.file("g.json")})
                .exit_code,
            0);
  EXPECT_EQ(nlohmann::json::parse(read_file(tmp.file("g.json")))["effects"].size(), 0u);
  // Given values win over drawn ones.
  const std::string fx = tmp.write("fx.json", R"({"accel_scale": [1000, 2000, 3000]})");
  ASSERT_EQ(run_sinu({"simulate", "static", "--out", tmp.file("c"), "--seed", "12", "--positions", "6", "--hold-s",
                      "20", "--effects", fx, "--hidden-out", tmp.file("c.json")})
                .exit_code,
            0);
  const auto hc = nlohmann::json::parse(read_file(tmp.file("c.json")));
  EXPECT_EQ(hc["effects"]["accel_scale"], nlohmann::json::parse("[1000.0, 2000.0, 3000.0]"));
  EXPECT_EQ(hc["effects"]["accel_misalign"], h["effects"]["accel_misalign"]);

  const std::string out = tmp.file("o");
  for (const std::vector<std::string>& bad : std::vector<std::vector<std::string>>{
           {"--positions", "4"}, {"--positions", "27"}, {"--positions", "6", "--hold-s", "5"},
           {"--positions", "6", "--hold-s", "20", "--duration", "600"},
           {"--positions", "6", "--hours", "0.01"}}) {
    std::vector<std::string> a = {"simulate", "static", "--out", out, "--seed", "1"};
    a.insert(a.end(), bad.begin(), bad.end());
    const auto e = run_sinu(a);
    EXPECT_EQ(e.exit_code, 2) << bad[1] << " " << e.err;
  }
  const auto few = run_sinu({"simulate", "static", "--out", out, "--seed", "1", "--positions", "3"});
  EXPECT_NE(few.err.find("--positions 3 must be 1 (level) or 6..26"), std::string::npos) << few.err;
  EXPECT_EQ(run_sinu({"simulate", "flight", "--out", out, "--seed", "1", "--positions", "6"}).exit_code, 2);
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
