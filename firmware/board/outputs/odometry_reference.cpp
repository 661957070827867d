#include "firmware/board/outputs/odometry_reference.hpp"

#include <cmath>
#include <numbers>

#include "estimator/earth/wgs84.hpp"
#include "estimator/nav/nav_health.hpp"

namespace sinu::board {

namespace {
constexpr double kRadPerDeg = std::numbers::pi / 180.0;
constexpr std::uint32_t kResetEvents =
    est::nav_flag::kPositionReset | est::nav_flag::kVelocityReset | est::nav_flag::kYawReset;
}  // namespace

void OdometryReference::observe(const NavSolution& sol) {
  if (sol.aligned && !has_origin_) {
    has_origin_ = true;
    lat0_rad_ = sol.lat_deg * kRadPerDeg;
    lon0_rad_ = sol.lon_deg * kRadPerDeg;
    h0_m_ = sol.h_ellipsoid_m;
  }
  if ((sol.flags & kResetEvents) != 0) reset_counter_ = static_cast<std::uint8_t>(reset_counter_ + 1);
}

Eigen::Vector3d OdometryReference::local_ned_m(const NavSolution& sol) const {
  if (!has_origin_) return Eigen::Vector3d::Zero();
  const double lat = sol.lat_deg * kRadPerDeg;
  const double dlat = lat - lat0_rad_;
  const double dlon = std::remainder(sol.lon_deg * kRadPerDeg - lon0_rad_, 2.0 * std::numbers::pi);  // across 180 deg
  const double lat_mean = lat0_rad_ + 0.5 * dlat;
  const double h_mean = 0.5 * (h0_m_ + sol.h_ellipsoid_m);
  const double north = dlat * (est::wgs84::meridian_radius_m(lat_mean) + h_mean);
  const double east = dlon * (est::wgs84::transverse_radius_m(lat_mean) + h_mean) * std::cos(lat_mean);
  return {north, east, h0_m_ - sol.h_ellipsoid_m};
}

}  // namespace sinu::board
