#include "firmware/board/gnss_from_fix.hpp"

#include "estimator/earth/geomagnetic_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sinu::board {

bool gnss_from_fix(const drivers::GpsFix& fix, const GnssSigmaConfig& cfg, est::GnssObservation& out) {
  constexpr double kDegToRad = std::numbers::pi / 180.0;
  constexpr int kRtkFixed = 4, kRtkFloat = 5;  // GGA fix quality
  if (!fix.has_position()) return false;
  const auto h = fix.ellipsoid_height_m();
  out = {};
  out.arrival_s = fix.arrival_s;
  out.has_position = true;
  out.lat_rad = *fix.lat_deg * kDegToRad;
  out.lon_rad = *fix.lon_deg * kDegToRad;
  out.has_height = h.has_value();  // RMC or GLL alone: north and east only (the navigator)
  out.h_m = h.value_or(NAN);
  Eigen::Vector3d sig;
  if (fix.has_gst && fix.sigma_lat_m && fix.sigma_lon_m && fix.sigma_alt_m) {
    sig = {*fix.sigma_lat_m, *fix.sigma_lon_m, *fix.sigma_alt_m};
  } else if (fix.quality == kRtkFixed || fix.quality == kRtkFloat) {
    const double s = fix.quality == kRtkFixed ? cfg.rtk_fixed_sigma_m : cfg.rtk_float_sigma_m;
    sig = {s, s, 2.0 * s};  // the receiver's claim: centimetres (fixed) or decimetres (float)
  } else if (fix.hdop) {
    const double vdop = fix.vdop.value_or(1.5 * *fix.hdop);
    sig = {*fix.hdop * cfg.uere_m / std::sqrt(2.0), *fix.hdop * cfg.uere_m / std::sqrt(2.0), vdop * cfg.uere_m};
    out.sigma_is_guess = true;
  } else {
    sig = Eigen::Vector3d::Constant(cfg.no_dop_sigma_m);
    out.sigma_is_guess = true;
  }
  for (Eigen::Index i = 0; i < 3; ++i) sig(i) = std::max(sig(i) * cfg.position_sigma_scale, cfg.min_sigma_m);
  out.sigma_ned_m = sig;
  if (fix.date) {
    out.decimal_year = est::geomag::decimal_year(fix.date->year, fix.date->month, fix.date->day,
                                                 static_cast<double>(fix.utc_ms) / 1000.0);
  }
  if (fix.has_velocity()) {
    out.has_velocity = true;
    const double course_rad = *fix.course_deg * kDegToRad;
    out.v_ne_m_s = *fix.speed_m_s * Eigen::Vector2d(std::cos(course_rad), std::sin(course_rad));
    out.sigma_vel_m_s = cfg.velocity_sigma_m_s;
  }
  return true;
}

}  // namespace sinu::board
