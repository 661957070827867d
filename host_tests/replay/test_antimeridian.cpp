// A flight across the antimeridian (180 deg E = 180 deg W: Fiji, the Aleutians,
// New Zealand's Chatham Islands). Found by moving a simulated flight there:
// the GNSS innovation took 179.9 E - 179.9 W as 359.8 deg, every fix was
// rejected and reset to, and the error against truth read 8.8e6 m (the
// scoring differenced longitudes the same way). Longitudes are now wrapped
// where the INS integrates them and differenced the short way
// (wgs84::lon_difference_rad).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "host_tests/support/nmea_text.hpp"
#include "host_tests/support/replay_helpers.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string f; std::getline(ss, f, sep);) out.push_back(f);
  if (!s.empty() && s.back() == sep) out.emplace_back();
  return out;
}

double wrap_deg(double lon) { return std::remainder(lon, 360.0); }

/// NMEA "dddmm.mmmm", "E"/"W" moved east by dlon_deg.
void shift_nmea_lon(std::string& value, std::string& hemi, double dlon_deg) {
  if (value.empty()) return;
  const double v = std::stod(value);
  const double deg = std::floor(v / 100.0);
  double lon = (deg + (v - 100.0 * deg) / 60.0) * (hemi == "W" ? -1.0 : 1.0);
  lon = wrap_deg(lon + dlon_deg);
  const double a = std::abs(lon), d = std::floor(a);
  char text[32];
  std::snprintf(text, sizeof text, "%03.0f%09.6f", d, (a - d) * 60.0);
  value = text;
  hemi = lon >= 0.0 ? "E" : "W";
}

/// A copy of `src` (and its truth) moved east by dlon_deg.
std::string moved_east(const std::string& src, const std::string& truth, const std::string& dst, double dlon_deg) {
  copy_dataset_editing_gps(src, dst, [&](std::string& line) {
    const auto star = line.find('*'), dollar = line.find('$');
    if (star == std::string::npos || dollar == std::string::npos) return true;
    const std::string original = line.substr(dollar + 1, star - dollar - 1);
    // A sentence the simulator corrupted on purpose stays corrupt (a new
    // checksum would make its garbage a fix).
    if (nmea_with_checksum(original) != line.substr(dollar)) return true;
    auto f = split(original, ',');
    const std::string type = f[0].size() >= 3 ? f[0].substr(f[0].size() - 3) : "";
    if (type == "GGA" && f.size() > 5) shift_nmea_lon(f[4], f[5], dlon_deg);
    if (type == "RMC" && f.size() > 6) shift_nmea_lon(f[5], f[6], dlon_deg);
    if (type == "GLL" && f.size() > 4) shift_nmea_lon(f[3], f[4], dlon_deg);
    std::string body;
    for (std::size_t i = 0; i < f.size(); ++i) body += (i ? "," : "") + f[i];
    line = line.substr(0, dollar) + nmea_with_checksum(body);
    return true;
  });
  std::ifstream in(truth);
  std::ofstream out(dst + "_truth.csv");
  std::string line;
  std::getline(in, line);
  out << line << '\n';
  while (std::getline(in, line)) {
    auto c = split(line, ',');
    char text[32];
    std::snprintf(text, sizeof text, "%.9f", wrap_deg(std::stod(c[2]) + dlon_deg));
    c[2] = text;
    for (std::size_t i = 0; i < c.size(); ++i) out << (i ? "," : "") << c[i];
    out << '\n';
  }
  return dst + "_truth.csv";
}

TEST(Antimeridian, AFlightAcrossItNavigatesAsWellAsAnywhereElse) {
  TempDir dir;
  const std::string ds = dir.file("flight");
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", ds, "--seed", "9", "--duration", "600"}).exit_code, 0);
  const std::string truth = dir.file("truth.csv");
  std::filesystem::rename(ds + "/truth.csv", truth);
  // Where the flight is: its middle truth row's longitude, moved onto 180 deg.
  std::vector<double> lons;
  {
    std::ifstream in(truth);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) lons.push_back(std::stod(split(line, ',')[2]));
  }
  ASSERT_FALSE(lons.empty());
  const double dlon = 180.0 - lons[lons.size() / 2];
  const std::string moved = dir.file("moved");
  const std::string moved_truth = moved_east(ds, truth, moved, dlon);
  // The magnetometer is left out: at the new place the World Magnetic Model's
  // field is not the one the simulator recorded (a field it does not
  // recognise, heading from the course), which would change the comparison.
  const auto here = replay_summary({"replay", "--in", ds, "--truth", truth, "--no-mag", "--quiet", "--out", dir.file("a")});
  const auto there = replay_summary(
      {"replay", "--in", moved, "--truth", moved_truth, "--no-mag", "--quiet", "--out", dir.file("b")});
  EXPECT_EQ(there["health"]["status"], "ok") << there["health"].dump();
  EXPECT_EQ(there["rejected"]["gnss_position"], here["rejected"]["gnss_position"]);
  EXPECT_EQ(there["health"]["resets"], here["health"]["resets"]);
  // The same flight: only the Earth's rotation and gravity depend on where,
  // and on the latitude only; 10 % allows for the receiver sentences'
  // rounding (1e-6 minute) and the converted truth. Measured: 0.542 / 0.545 m.
  const double a = here["rmse"]["pos_h_m"].get<double>(), b = there["rmse"]["pos_h_m"].get<double>();
  EXPECT_NEAR(b, a, 0.1 * a) << "here " << a << " m, across 180 deg " << b << " m";
  EXPECT_LT(there["gnss_only_rmse"]["pos_h_m"].get<double>(), 5.0) << "the scoring differences the short way";
}

}  // namespace
}  // namespace sinu::test
