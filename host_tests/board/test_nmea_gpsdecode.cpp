// What the NMEA output writes, decoded by gpsd's own decoder: gpsdecode(1)
// reads NMEA on stdin and prints gpsd's JSON reports, one TPV (time,
// position, velocity) and one GST per epoch. Each is checked against the
// NavSolution it was written from, within the written resolution plus
// gpsdecode's own print rounding (lat/lon 9 decimals, altitudes and track 4,
// speed and GST 3).
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "firmware/board/outputs/nmea_sentences.hpp"
#include "host_tests/board/nmea_output_cases.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace {

using sinu::board::NavSolution;
namespace t = sinu::test;
using nlohmann::json;

constexpr const char* kGpsdecode = "/usr/bin/gpsdecode";

// gpsdecode prints lat/lon with 9 decimals, altitudes and track with 4,
// speed and the GST values with 3: half of each step adds to our rounding.
constexpr double kGpsdLatLonPrint_deg = 0.5e-9;
constexpr double kGpsdAltPrint_m = 0.5e-4;
constexpr double kGpsdTrackPrint_deg = 0.5e-4;
constexpr double kGpsdSpeedPrint_m_s = 0.5e-3;

/// "2026-03-22T10:15:20.123Z": how gpsd writes a UTC instant (to the ms).
std::string iso_time(std::int64_t utc_ms) {
  using namespace std::chrono;
  const sys_time<milliseconds> tp{milliseconds{utc_ms}};
  const auto day = floor<days>(tp);
  const year_month_day ymd{day};
  const hh_mm_ss<milliseconds> tod{tp - day};
  char buf[40];
  std::snprintf(buf, sizeof buf, "%04d-%02u-%02uT%02d:%02d:%02d.%03dZ", static_cast<int>(ymd.year()),
                static_cast<unsigned>(ymd.month()), static_cast<unsigned>(ymd.day()),
                static_cast<int>(tod.hours().count()), static_cast<int>(tod.minutes().count()),
                static_cast<int>(tod.seconds().count()), static_cast<int>(tod.subseconds().count()));
  return buf;
}

/// The sentences of `solutions` through gpsdecode: its reports by class.
struct GpsdReports {
  std::vector<json> tpv, gst;
};
GpsdReports gpsdecode(const std::vector<NavSolution>& solutions) {
  std::string bytes;
  std::array<char, sinu::board::kNmeaEpochMax> buf{};
  for (const auto& n : solutions) bytes.append(buf.data(), sinu::board::write_nmea_epoch(n, sinu::board::NmeaTalker::GP, buf));
  t::TempDir dir;
  const std::string in = dir.write("out.nmea", bytes);
  const auto r = t::run_process({"/bin/sh", "-c", std::string("exec ") + kGpsdecode + " < '" + in + "'"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  GpsdReports reports;
  std::istringstream lines(r.out);
  for (std::string l; std::getline(lines, l);) {
    const json j = json::parse(l);
    if (j.at("class") == "TPV") reports.tpv.push_back(j);
    if (j.at("class") == "GST") reports.gst.push_back(j);
  }
  return reports;
}

const json* report_at(const std::vector<json>& reports, const std::string& time) {
  for (const auto& j : reports)
    if (j.value("time", "") == time) return &j;
  return nullptr;
}

/// gpsd learns a receiver's cycle from its first epoch and reports no TPV for
/// it (it also wants the date first: RMC leads the epoch for that). The
/// stream therefore starts with one epoch of the same solution a second earlier.
std::vector<NavSolution> with_primer(std::vector<NavSolution> cases) {
  NavSolution primer = cases.front();
  primer.utc_ms -= 1000;
  cases.insert(cases.begin(), primer);
  return cases;
}

#define SKIP_WITHOUT_GPSDECODE()                                                                          \
  if (::access(kGpsdecode, X_OK) != 0)                                                                    \
  GTEST_SKIP() << kGpsdecode << " is not installed (Debian package gpsd-clients, tools/setup.sh): "      \
               << "the cross-check against gpsd's decoder is skipped"

}  // namespace

TEST(NmeaGpsdecode, PositionVelocityAndTimeAsGpsdDecodesThem) {
  SKIP_WITHOUT_GPSDECODE();
  const std::vector<NavSolution> cases = t::hemisphere_cases();
  const GpsdReports r = gpsdecode(with_primer(cases));
  EXPECT_EQ(r.tpv.size(), cases.size());
  for (const auto& n : cases) {
    const std::string time = iso_time(n.utc_ms);
    SCOPED_TRACE(time);
    const json* tpv = report_at(r.tpv, time);  // the time matches to the millisecond
    ASSERT_NE(tpv, nullptr);
    EXPECT_EQ(tpv->at("mode").get<int>(), 3);  // 3-D fix
    EXPECT_NEAR(tpv->at("lat").get<double>(), n.lat_deg, t::kAngleTol_deg + kGpsdLatLonPrint_deg);
    EXPECT_NEAR(t::angle_diff_deg(tpv->at("lon").get<double>(), n.lon_deg), 0.0,
                t::kAngleTol_deg + kGpsdLatLonPrint_deg);
    EXPECT_NEAR(tpv->at("altMSL").get<double>(), n.h_ellipsoid_m - n.geoid_sep_m, t::kMetreTol_m + kGpsdAltPrint_m);
    EXPECT_NEAR(tpv->at("geoidSep").get<double>(), n.geoid_sep_m, t::kMetreTol_m + 0.5e-3);  // printed to 3
    // gpsd adds the two rounded fields: HAE carries both roundings.
    EXPECT_NEAR(tpv->at("altHAE").get<double>(), n.h_ellipsoid_m, 2 * t::kMetreTol_m + kGpsdAltPrint_m);
    EXPECT_NEAR(tpv->at("speed").get<double>(), n.v_ned_m_s.head<2>().norm(), t::kSpeedTol_m_s + kGpsdSpeedPrint_m_s);
    if (n.v_ned_m_s.head<2>().norm() > 0.0) {
      EXPECT_NEAR(t::angle_diff_deg(tpv->at("track").get<double>(), t::course_deg(n)), 0.0,
                  t::kCourseTol_deg + kGpsdTrackPrint_deg);
    }
  }
}

TEST(NmeaGpsdecode, ErrorStatisticsAsGpsdDecodesThem) {
  SKIP_WITHOUT_GPSDECODE();
  const std::vector<NavSolution> cases = t::hemisphere_cases();
  const GpsdReports r = gpsdecode(with_primer(cases));
  // gpsd prints GST values with the 3 decimals we wrote: the tolerance is our rounding.
  for (const auto& n : cases) {
    const std::string time = iso_time(n.utc_ms);
    SCOPED_TRACE(time);
    const json* gst = report_at(r.gst, time);
    ASSERT_NE(gst, nullptr);
    const t::ExpectedEllipse e = t::expected_ellipse(n);
    EXPECT_NEAR(gst->at("lat").get<double>(), std::sqrt(n.P_nav(0, 0)), t::kMetreTol_m);
    EXPECT_NEAR(gst->at("lon").get<double>(), std::sqrt(n.P_nav(1, 1)), t::kMetreTol_m);
    EXPECT_NEAR(gst->at("alt").get<double>(), std::sqrt(n.P_nav(2, 2)), t::kMetreTol_m);
    EXPECT_NEAR(gst->at("major").get<double>(), e.major_m, t::kMetreTol_m);
    EXPECT_NEAR(gst->at("minor").get<double>(), e.minor_m, t::kMetreTol_m);
    EXPECT_NEAR(gst->at("orient").get<double>(), e.orient_deg, t::kOrientTol_deg);
    EXPECT_NEAR(gst->at("rms").get<double>(), std::sqrt(n.P_nav.block<3, 3>(0, 0).trace()), t::kMetreTol_m);
  }
}

TEST(NmeaGpsdecode, NotAlignedIsNoFixForGpsd) {
  SKIP_WITHOUT_GPSDECODE();
  std::vector<NavSolution> cases = t::hemisphere_cases();
  for (auto& n : cases) n.aligned = false;
  const GpsdReports r = gpsdecode(with_primer(cases));
  EXPECT_EQ(r.tpv.size(), cases.size());
  for (const auto& j : r.tpv) {
    SCOPED_TRACE(j.dump());
    EXPECT_EQ(j.at("mode").get<int>(), 1);  // no fix
    EXPECT_FALSE(j.contains("lat"));
    EXPECT_FALSE(j.contains("lon"));
  }
}

TEST(NmeaGpsdecode, MidnightRolloverChangesGpsdsDate) {
  SKIP_WITHOUT_GPSDECODE();
  NavSolution a = t::hemisphere_cases()[1];
  a.utc_ms = t::utc_ms(2025, 12, 31, 23, 59, 59, 900);
  NavSolution b = a;
  b.utc_ms += 200;
  const GpsdReports r = gpsdecode(with_primer({a, b}));
  EXPECT_NE(report_at(r.tpv, "2025-12-31T23:59:59.900Z"), nullptr);
  EXPECT_NE(report_at(r.tpv, "2026-01-01T00:00:00.100Z"), nullptr);
}
