// What the levelling at rest tells the filter, and what it does not. A unit
// whose accelerometer x and y sense z (xz, yz of its misalignment) reads
// -xz g and -yz g on those axes standing level: the levelling takes that as a
// tilt of 1-1.5 deg, just as it takes a horizontal bias. The tilt error is
// then the sum of all of them over g, and the rest's vertical mean measures
// only the sum along gravity: none of them on its own. Before, the tilt was
// correlated with the bias alone, so the 20 seconds at rest "taught" xz and
// yz to 2.7 mrad (their prior 20), at zero, and the flight never moved them
// to the truth (-9.3 +- 1.7 against -20 mrad, 14.9 +- 1.6 against 25).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "host_tests/support/nav_error.hpp"
#include "host_tests/support/read_json.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

/// A 20-minute flight of a unit with `effects_json` (its bench session of 1 h,
/// the same seed, calibrated), replayed with that effect's states and 1-Hz
/// rows. Returns the output folder ("" after a failure, reported).
std::string replay_unit(const TempDir& dir, const std::string& effects_json, const std::string& seed,
                        const std::string& effect) {
  const std::string effects = dir.write("unit.json", effects_json);
  const std::string flight = dir.file("flight"), bench = dir.file("bench"), calib = dir.file("calib.json");
  const std::string out = dir.file("r");
  for (const auto& args : {std::vector<std::string>{"simulate", "flight", "--out", flight, "--seed", seed, "--duration",
                                                    "1200", "--effects", effects},
                           std::vector<std::string>{"simulate", "static", "--out", bench, "--seed", seed, "--hours", "1"},
                           std::vector<std::string>{"calibrate", "--in", bench, "--out", calib, "--quiet"},
                           std::vector<std::string>{"replay", "--in", flight, "--calib", calib, "--effects", effect,
                                                    "--nav-rate", "1", "--quiet", "--out", out}}) {
    const auto r = run_sinu(args);
    if (r.exit_code != 0) {
      ADD_FAILURE() << args[0] << ": " << r.err;
      return "";
    }
  }
  return out;
}

TEST(RestLevelling, ACrossAxisTermTheLevellingTookForATiltIsLearntInFlightNotAtRest) {
  TempDir dir;
  const std::string out = replay_unit(
      dir, R"({"accel_misalign": [[0, 0.015, -0.020], [0.010, 0, 0.025], [-0.012, 0.018, 0]]})", "4321", "accel_misalign");
  ASSERT_FALSE(out.empty());

  // Aligned at rest, still standing 10 s later (the flight takes off after
  // about a minute): the rest has said nothing of xz and yz on their own
  // (their prior sigma is 20 mrad; before, 3.2 and 2.8 mrad here).
  EXPECT_GT(nav_value_after(out + "/nav.csv", "sigma_accel_misalign_xz", 10.0), 0.9 * 0.020);
  EXPECT_GT(nav_value_after(out + "/nav.csv", "sigma_accel_misalign_yz", 10.0), 0.9 * 0.020);

  // After the flight (turns at 1.1-1.2 g give f_z its span): both where the
  // unit has them, within 3 sigma, and the sigma not claiming more than the
  // error shows (measured -17.1 +- 2.1 and 25.5 +- 2.0 mrad).
  const auto s = read_json(out + "/summary.json");
  const auto e = summary_effect(s, "accel_misalign");
  ASSERT_FALSE(e.is_null()) << "summary.json has no accel_misalign estimate";
  const double xz = e["estimate"][1].get<double>(), yz = e["estimate"][3].get<double>();
  const double sxz = e["sigma"][1].get<double>(), syz = e["sigma"][3].get<double>();
  EXPECT_LT(std::abs(xz - (-0.020)), 3.0 * sxz) << xz << " +- " << sxz;
  EXPECT_LT(std::abs(yz - 0.025), 3.0 * syz) << yz << " +- " << syz;
}

// The gyro's twin: at rest a g-sensitivity's column along gravity (G_xz,
// G_yz, G_zz times -g) is in the mean rate the bias is seeded from. With the
// bias's sigma the mean's noise alone, level flight held that column at zero
// and the turns' load factor could not move it (seed 5555: xz -0.019 +-
// 0.036, yz 0.027 +- 0.026, zz 0.046 +- 0.032 against -0.2, 0.1, 0.25
// deg/s/g). The bias now carries the column's error (d b = g dG_z).
TEST(RestLevelling, AGSensitivityTheRestHidInTheGyroBiasIsLearntFromTheLoadFactor) {
  TempDir dir;
  constexpr double k = 3.14159265358979 / 180.0 / 9.80665;  // deg/s/g -> rad/s per m/s^2
  char spec[256];
  std::snprintf(spec, sizeof spec, R"({"gyro_g_sensitivity": [[%.9g, 0, %.9g], [0, %.9g, %.9g], [0, 0, %.9g]]})",
                0.05 * k, -0.2 * k, 0.05 * k, 0.1 * k, 0.25 * k);
  const std::string out = replay_unit(dir, spec, "5555", "gyro_g_sensitivity");
  ASSERT_FALSE(out.empty());
  const auto s = read_json(out + "/summary.json");
  // Row-major: xz, yz, zz are components 2, 5, 8. Measured -0.176 +- 0.056,
  // 0.088 +- 0.052, 0.197 +- 0.078 deg/s/g: each within 3 sigma of the unit's.
  const std::pair<std::size_t, double> column_z[] = {{2, -0.2 * k}, {5, 0.1 * k}, {8, 0.25 * k}};
  const auto e = summary_effect(s, "gyro_g_sensitivity");
  ASSERT_FALSE(e.is_null()) << "summary.json has no gyro_g_sensitivity estimate";
  for (const auto& [i, truth] : column_z) {
    const double v = e["estimate"][i].get<double>(), sg = e["sigma"][i].get<double>();
    EXPECT_LT(std::abs(v - truth), 3.0 * sg) << "component " << i << ": " << v / k << " +- " << sg / k << " deg/s/g";
  }
}

// Along gravity the rest measures a sum too: the bias and g times the z
// scale. Given to the bias with the mean's noise alone, the bias was as sure
// as that, and the fixes' vertical then "measured" the z scale through it
// (its sigma 0.41 % 10 s into the rest, prior 2 %): the flight held it at
// 0.35 +- 0.10 % against a true 1 % (seed 4321). The bias now carries the
// other terms' share as noise of its own.
TEST(RestLevelling, AZScaleTheRestGaveTheBiasIsLearntFromTheLoadFactor) {
  TempDir dir;
  const std::string out = replay_unit(dir, R"({"accel_scale": [0, 0, 10000]})", "4321", "accel_scale");  // ppm
  ASSERT_FALSE(out.empty());
  // The rest cannot tell the two apart: the z scale keeps most of its prior
  // (2 %). The fixes at rest pin their sum, which halves the variance of
  // each when both start independent: 1.4 % measured, so 0.5 of the prior.
  EXPECT_GT(nav_value_after(out + "/nav.csv", "sigma_accel_scale_z", 10.0), 0.5 * 0.02);
  const auto s = read_json(out + "/summary.json");
  const auto e = summary_effect(s, "accel_scale");
  ASSERT_FALSE(e.is_null()) << "summary.json has no accel_scale estimate";
  // Measured 0.996 +- 0.161 %: within 3 sigma of the unit's 1 %.
  const double z = e["estimate"][2].get<double>(), sz = e["sigma"][2].get<double>();
  EXPECT_LT(std::abs(z - 0.01), 3.0 * sz) << z << " +- " << sz;
}

}  // namespace
}  // namespace sinu::test
