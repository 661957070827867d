#include "estimator/align/position_velocity.hpp"

#include <cmath>
#include <numbers>

#include "estimator/earth/wgs84.hpp"

namespace sinu::est {

bool PositionVelocity::fill(GnssObservation& z) {
  if (!z.has_position || !std::isfinite(z.lat_rad) || !std::isfinite(z.lon_rad)) return false;
  const double sigma_h = z.sigma_ned_m.head<2>().maxCoeff();
  bool filled = false;
  if (!z.has_velocity) {
    // The newest fix at least baseline_s older (the ring holds them oldest first from next_).
    for (std::size_t k = 0; k < count_; ++k) {
      const Fix& f = fixes_[(next_ + kFixes - 1 - k) % kFixes];
      const double dt = z.arrival_s - f.t_s;
      if (dt < cfg_.baseline_s) continue;
      if (dt > cfg_.max_baseline_s) break;
      const double north_m = (z.lat_rad - f.lat_rad) * (wgs84::meridian_radius_m(z.lat_rad) + z.h_m);
      const double east_m =
          wgs84::lon_difference_rad(z.lon_rad, f.lon_rad) * (wgs84::transverse_radius_m(z.lat_rad) + z.h_m) *
          std::cos(z.lat_rad);
      z.v_ne_m_s = {north_m / dt, east_m / dt};
      const double white = std::sqrt(cfg_.white_fraction * (sigma_h * sigma_h + f.sigma_h_m * f.sigma_h_m)) / dt;
      z.sigma_vel_m_s = std::hypot(white, 0.5 * cfg_.lag_accel_m_s2 * dt);
      z.has_velocity = z.velocity_from_positions = true;
      filled = true;
      break;
    }
  }
  fixes_[next_] = {z.arrival_s, z.lat_rad, z.lon_rad, sigma_h};
  next_ = (next_ + 1) % kFixes;
  if (count_ < kFixes) ++count_;
  return filled;
}

}  // namespace sinu::est
