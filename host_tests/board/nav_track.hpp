#pragma once
// NavSolutions for the MAVLink tests: a fixed attitude, velocity and a full,
// correlated P_nav (so that every cross term, and its sign, shows), and a
// straight track at constant velocity from a known origin.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "estimator/earth/wgs84.hpp"
#include "estimator/nav/nav_health.hpp"
#include "firmware/board/nav_solution.hpp"

namespace sinu::test {

inline constexpr double kDeg = std::numbers::pi / 180.0;

/// body FRD -> NED from roll, pitch, yaw [rad] (ZYX).
inline Eigen::Quaterniond q_from_rpy(double roll, double pitch, double yaw) {
  return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
}

/// A symmetric positive-definite 9x9 with position sigmas ~1-3 m, velocity
/// ~0.1-0.3 m/s, attitude ~0.005-0.02 rad, and correlations between all blocks.
inline Eigen::Matrix<double, 9, 9> correlated_P(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Matrix<double, 9, 9> A;
  for (int r = 0; r < 9; ++r)
    for (int c = 0; c < 9; ++c) A(r, c) = (r == c ? 1.0 : 0.4 * u(rng));
  Eigen::Matrix<double, 9, 1> scale;
  scale << 1.5, 2.5, 3.0, 0.1, 0.2, 0.3, 0.005, 0.01, 0.02;
  A = scale.asDiagonal() * A;
  return A * A.transpose();
}

inline board::NavSolution sample_solution() {
  board::NavSolution s;
  s.t_s = 12.345678;
  s.has_utc = true;
  s.utc_ms = 1'774'174'520'400;  // 2026-03-22T10:15:20.400Z
  s.aligned = true;
  s.lat_deg = 30.4085390;
  s.lon_deg = 114.3520575;
  s.h_ellipsoid_m = 45.3;
  s.geoid_sep_m = -12.1;
  s.v_ned_m_s = {8.0, -3.0, 0.5};
  s.q_nb = q_from_rpy(10.0 * kDeg, -5.0 * kDeg, 120.0 * kDeg);
  s.angular_rate_b_rad_s = {0.02, -0.01, 0.15};
  s.P_nav = correlated_P(7);
  s.flags = est::nav_flag::kAligned;
  s.satellites = 14;
  s.hdop = 0.8;
  return s;
}

/// Geodetic position of the point `d_ned_m` from (lat0, lon0, h0) on the
/// tangent plane (through ECEF: independent of the encoder's radii).
inline Eigen::Vector3d geodetic_at(double lat0_deg, double lon0_deg, double h0_m, const Eigen::Vector3d& d_ned_m) {
  namespace w = est::wgs84;
  const Eigen::Vector3d r0 = w::geodetic_to_ecef(lat0_deg * kDeg, lon0_deg * kDeg, h0_m);
  const Eigen::Vector3d llh = w::ecef_to_geodetic(r0 + w::C_en(lat0_deg * kDeg, lon0_deg * kDeg) * d_ned_m);
  return {llh.x() / kDeg, llh.y() / kDeg, llh.z()};
}

/// The track: aligned from `aligned_from_s`, 5 m/s north and 2 m/s east from
/// the sample position, a position reset event at `reset_at_s`.
struct Track {
  double aligned_from_s = 0.5;
  double reset_at_s = 10.0;
  double dt_s = 0.02;  // 50 Hz solutions

  board::NavSolution at(int k) const {
    board::NavSolution s = sample_solution();
    s.t_s = k * dt_s;
    s.utc_ms = 1'774'174'520'000 + static_cast<std::int64_t>(std::llround(s.t_s * 1000.0));
    s.aligned = s.t_s >= aligned_from_s - 1e-9;
    s.v_ned_m_s = {5.0, 2.0, 0.0};
    const Eigen::Vector3d llh = geodetic_at(30.4085390, 114.3520575, 45.3, s.v_ned_m_s * s.t_s);
    s.lat_deg = llh.x();
    s.lon_deg = llh.y();
    s.h_ellipsoid_m = llh.z();
    s.flags = s.aligned ? est::nav_flag::kAligned : 0u;
    if (std::abs(s.t_s - reset_at_s) < 1e-9) s.flags |= est::nav_flag::kPositionReset;
    return s;
  }
};

}  // namespace sinu::test
