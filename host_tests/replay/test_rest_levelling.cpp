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
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "host_tests/support/read_json.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

/// The nav.csv row `after_s` past its first one, as column name -> value.
std::vector<std::pair<std::string, double>> row_after(const std::string& nav_csv, double after_s) {
  std::ifstream in(nav_csv);
  std::string header, row;
  std::getline(in, header);
  double t0 = NAN;
  while (std::getline(in, row)) {
    const double t = std::stod(row.substr(0, row.find(',')));
    if (std::isnan(t0)) t0 = t;
    if (t >= t0 + after_s) break;
  }
  std::stringstream h(header), r(row);
  std::vector<std::pair<std::string, double>> out;
  for (std::string name, value; std::getline(h, name, ',') && std::getline(r, value, ',');)
    out.emplace_back(name, value.empty() ? NAN : std::stod(value));
  return out;
}

double column(const std::vector<std::pair<std::string, double>>& row, const std::string& name) {
  for (const auto& [n, v] : row)
    if (n == name) return v;
  ADD_FAILURE() << "nav.csv has no column " << name;
  return NAN;
}

TEST(RestLevelling, ACrossAxisTermTheLevellingTookForATiltIsLearntInFlightNotAtRest) {
  TempDir dir;
  const std::string effects = dir.write("unit.json", R"({"accel_misalign": [[0, 0.015, -0.020], [0.010, 0, 0.025], [-0.012, 0.018, 0]]})");
  const std::string flight = dir.file("flight"), bench = dir.file("bench"), calib = dir.file("calib.json");
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", flight, "--seed", "4321", "--duration", "1200", "--effects", effects})
                .exit_code, 0);
  ASSERT_EQ(run_sinu({"simulate", "static", "--out", bench, "--seed", "4321", "--hours", "1"}).exit_code, 0);
  ASSERT_EQ(run_sinu({"calibrate", "--in", bench, "--out", calib, "--quiet"}).exit_code, 0);
  const std::string out = dir.file("r");
  const auto r = run_sinu({"replay", "--in", flight, "--calib", calib, "--effects", "accel_misalign", "--nav-rate", "1",
                           "--quiet", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;

  // Aligned at rest, still standing 10 s later (the flight takes off after
  // about a minute): the rest has said nothing of xz and yz on their own
  // (their prior sigma is 20 mrad; before, 3.2 and 2.8 mrad here).
  const auto row = row_after(out + "/nav.csv", 10.0);
  EXPECT_GT(column(row, "sigma_accel_misalign_xz"), 0.9 * 0.020);
  EXPECT_GT(column(row, "sigma_accel_misalign_yz"), 0.9 * 0.020);

  // After the flight (turns at 1.1-1.2 g give f_z its span): both where the
  // unit has them, within 3 sigma, and the sigma not claiming more than the
  // error shows (measured -17.1 +- 2.1 and 25.5 +- 2.0 mrad).
  const auto s = read_json(out + "/summary.json");
  for (const auto& e : s["effects"]) {
    if (e["name"] != "accel_misalign") continue;
    const double xz = e["estimate"][1].get<double>(), yz = e["estimate"][3].get<double>();
    const double sxz = e["sigma"][1].get<double>(), syz = e["sigma"][3].get<double>();
    EXPECT_LT(std::abs(xz - (-0.020)), 3.0 * sxz) << xz << " +- " << sxz;
    EXPECT_LT(std::abs(yz - 0.025), 3.0 * syz) << yz << " +- " << syz;
    return;
  }
  ADD_FAILURE() << "summary.json has no accel_misalign estimate";
}

}  // namespace
}  // namespace sinu::test
