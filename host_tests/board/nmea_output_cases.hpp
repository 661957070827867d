#pragma once
// Navigation solutions for the NMEA output tests, the resolution of what the
// output writes (the tolerances every comparison uses), and a decoder through
// the project's own NMEA stream (lexer, parser, fix assembler).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "drivers/gps/nmea_stream.hpp"
#include "firmware/board/nav_solution.hpp"

namespace sinu::test {

inline constexpr double kKnot_m_s = 1852.0 / 3600.0;
// Half a step of each written field: the most rounding can move a value.
// The 1e-12 absorbs the binary representation of the decimal step.
inline constexpr double kAngleTol_deg = 0.5e-6 / 60.0 + 1e-12;  // 6 decimals of a minute
inline constexpr double kMetreTol_m = 0.5e-3 + 1e-12;           // 3 decimals of a metre
inline constexpr double kSpeedTol_m_s = 0.5e-3 * kKnot_m_s + 1e-12;  // 3 decimals of a knot
inline constexpr double kCourseTol_deg = 0.005 + 1e-12;        // 2 decimals of a degree
inline constexpr double kOrientTol_deg = 0.05 + 1e-12;         // 1 decimal of a degree

/// UTC in ms since 1970 of a civil date and time.
inline std::int64_t utc_ms(int y, unsigned mo, unsigned d, int h, int mi, int s, int ms) {
  using namespace std::chrono;
  const sys_days day{year{y} / month{mo} / std::chrono::day{d}};
  return static_cast<std::int64_t>(day.time_since_epoch().count()) * 86'400'000 +
         ((h * 60 + mi) * 60 + s) * 1000LL + ms;
}

/// An aligned solution with a correlated horizontal covariance.
inline board::NavSolution solution(double lat_deg, double lon_deg, std::int64_t utc, Eigen::Vector3d v_ned) {
  board::NavSolution n;
  n.t_s = 100.0;
  n.has_utc = true;
  n.utc_ms = utc;
  n.aligned = true;
  n.lat_deg = lat_deg;
  n.lon_deg = lon_deg;
  n.h_ellipsoid_m = 512.3456789;
  n.geoid_sep_m = -28.7654321;
  n.v_ned_m_s = v_ned;
  n.P_nav.setZero();
  n.P_nav(0, 0) = 0.0912345;
  n.P_nav(1, 1) = 0.0456789;
  n.P_nav(0, 1) = n.P_nav(1, 0) = 0.0234567;
  n.P_nav(2, 2) = 0.2598765;
  n.P_nav.block<6, 6>(3, 3).setIdentity();
  n.flags = 1u;  // aligned
  n.satellites = 14;
  n.hdop = 0.73;
  return n;
}

/// The cases every decoding test runs: both hemispheres of both axes, a
/// course through each quadrant, odd milliseconds, the date line, and the
/// error ellipse turned a different way in each.
inline std::vector<board::NavSolution> hemisphere_cases() {
  const std::int64_t t0 = utc_ms(2026, 3, 22, 10, 15, 20, 123);
  std::vector<board::NavSolution> cases = {
      solution(30.408539123, 114.352057601, t0, {10.1, 3.2, -0.4}),           // N E, course NNE
      solution(-33.856789123, -70.661234567, t0 + 200, {-3.2, -10.1, 0.5}),   // S W, course WSW
      solution(-0.000000412, 0.000000377, t0 + 400, {-5.0, 5.0, 0.0}),        // S E at the origin, SE
      solution(51.477928888, -0.001475555, t0 + 600, {4.0, -4.0, 1.0}),       // N W, course NW
      solution(-45.123456789, 179.999999999, t0 + 801, {0.0, 0.0, 0.0}),      // S E at the date line, still
      solution(64.1, -179.999999999, t0 + 999, {25.0, -0.0001, 0.0}),          // N W, course ~360
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const double a = 0.55 * static_cast<double>(i);  // 31.5 deg steps
    const Eigen::Matrix2d R{{std::cos(a), -std::sin(a)}, {std::sin(a), std::cos(a)}};
    const Eigen::Matrix2d P = R * cases[i].P_nav.block<2, 2>(0, 0) * R.transpose();
    cases[i].P_nav.block<2, 2>(0, 0) = P;
  }
  return cases;
}

/// The error ellipse of the horizontal covariance from Eigen's eigen solver
/// (independent of the output's closed form): semi-major, semi-minor,
/// orientation of the major axis clockwise from north in [0, 180).
struct ExpectedEllipse {
  double major_m, minor_m, orient_deg;
};
inline ExpectedEllipse expected_ellipse(const board::NavSolution& n) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(n.P_nav.block<2, 2>(0, 0));
  const Eigen::Vector2d major = es.eigenvectors().col(1);  // eigenvalues ascend
  double deg = std::atan2(major.y(), major.x()) * 180.0 / 3.14159265358979323846;
  while (deg < 0.0) deg += 180.0;
  while (deg >= 180.0) deg -= 180.0;
  return {std::sqrt(es.eigenvalues()(1)), std::sqrt(es.eigenvalues()(0)), deg};
}

/// Course over ground of the solution [deg, 0..360).
inline double course_deg(const board::NavSolution& n) {
  double deg = std::atan2(n.v_ned_m_s.y(), n.v_ned_m_s.x()) * 180.0 / 3.14159265358979323846;
  return deg < 0.0 ? deg + 360.0 : deg;
}

/// Difference of two angles in degrees, wrapped to (-180, 180].
inline double angle_diff_deg(double a, double b) { return std::remainder(a - b, 360.0); }

/// Fixes the project's NMEA stream assembles from `bytes`, and its counters.
struct Decoded {
  std::vector<drivers::GpsFix> fixes;
  drivers::NmeaStreamCounters counters;
};
inline Decoded decode_with_project_parser(std::string_view bytes) {
  drivers::NmeaStream stream;
  Decoded d;
  drivers::GpsFix fix;
  for (char c : bytes)
    if (stream.push(c, 0.0, fix)) d.fixes.push_back(fix);
  if (stream.finish(0.0, fix)) d.fixes.push_back(fix);
  d.counters = stream.counters();
  return d;
}

/// The fix the project's parser assembled agrees with the solution it was
/// written from, to the resolution of each field.
inline void expect_fix_matches(const drivers::GpsFix& f, const board::NavSolution& n) {
  using namespace std::chrono;
  EXPECT_EQ(f.utc_ms, ((n.utc_ms % 86'400'000) + 86'400'000) % 86'400'000);  // written to the ms
  const year_month_day ymd{floor<days>(sys_time<milliseconds>{milliseconds{n.utc_ms}})};
  ASSERT_TRUE(f.date.has_value());
  EXPECT_EQ(*f.date, (drivers::UtcDate{static_cast<int>(ymd.year()), static_cast<int>(static_cast<unsigned>(ymd.month())),
                                       static_cast<int>(static_cast<unsigned>(ymd.day()))}));
  EXPECT_TRUE(f.has_position());
  EXPECT_EQ(f.quality, 1);
  EXPECT_TRUE(f.rmc_valid);
  ASSERT_TRUE(f.lat_deg && f.lon_deg && f.alt_msl_m && f.geoid_sep_m && f.speed_m_s && f.course_deg);
  EXPECT_NEAR(*f.lat_deg, n.lat_deg, kAngleTol_deg);
  EXPECT_NEAR(angle_diff_deg(*f.lon_deg, n.lon_deg), 0.0, kAngleTol_deg);
  EXPECT_NEAR(*f.alt_msl_m, n.h_ellipsoid_m - n.geoid_sep_m, kMetreTol_m);
  EXPECT_NEAR(*f.geoid_sep_m, n.geoid_sep_m, kMetreTol_m);
  EXPECT_NEAR(*f.ellipsoid_height_m(), n.h_ellipsoid_m, 2 * kMetreTol_m);  // two rounded fields added
  EXPECT_EQ(f.sats, n.satellites);
  EXPECT_NEAR(*f.hdop, n.hdop, 0.005 + 1e-12);  // 2 decimals
  EXPECT_NEAR(*f.speed_m_s, n.v_ned_m_s.head<2>().norm(), kSpeedTol_m_s);
  if (n.v_ned_m_s.head<2>().norm() > 0.0) {
    EXPECT_NEAR(angle_diff_deg(*f.course_deg, course_deg(n)), 0.0, kCourseTol_deg);
  }
  ASSERT_TRUE(f.sigma_lat_m && f.sigma_lon_m && f.sigma_alt_m);
  EXPECT_NEAR(*f.sigma_lat_m, std::sqrt(n.P_nav(0, 0)), kMetreTol_m);
  EXPECT_NEAR(*f.sigma_lon_m, std::sqrt(n.P_nav(1, 1)), kMetreTol_m);
  EXPECT_NEAR(*f.sigma_alt_m, std::sqrt(n.P_nav(2, 2)), kMetreTol_m);
}

}  // namespace sinu::test
