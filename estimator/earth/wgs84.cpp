#include "estimator/earth/wgs84.hpp"

#include <cmath>

namespace sinu::est::wgs84 {

double meridian_radius_m(double lat_rad) {
  const double s = std::sin(lat_rad);
  const double d = 1.0 - kE2 * s * s;
  return kA * (1.0 - kE2) / (d * std::sqrt(d));
}

double transverse_radius_m(double lat_rad) {
  const double s = std::sin(lat_rad);
  return kA / std::sqrt(1.0 - kE2 * s * s);
}

double normal_gravity_m_s2(double lat_rad, double h_m) {
  const double s2 = std::sin(lat_rad) * std::sin(lat_rad);
  const double g0 = kGammaEquator * (1.0 + kSomiglianaK * s2) / std::sqrt(1.0 - kE2 * s2);
  const double m = kOmegaIe * kOmegaIe * kA * kA * kB / kGM;
  return g0 * (1.0 - 2.0 / kA * (1.0 + kF + m - 2.0 * kF * s2) * h_m + 3.0 * h_m * h_m / (kA * kA));
}

Eigen::Vector3d omega_ie_n(double lat_rad) {
  return {kOmegaIe * std::cos(lat_rad), 0.0, -kOmegaIe * std::sin(lat_rad)};
}

Eigen::Vector3d omega_en_n(double lat_rad, double h_m, const Eigen::Vector3d& v) {
  const double rm = meridian_radius_m(lat_rad) + h_m;
  const double rn = transverse_radius_m(lat_rad) + h_m;
  return {v.y() / rn, -v.x() / rm, -v.y() * std::tan(lat_rad) / rn};
}

Eigen::Vector3d geodetic_to_ecef(double lat, double lon, double h) {
  const double rn = transverse_radius_m(lat);
  return {(rn + h) * std::cos(lat) * std::cos(lon), (rn + h) * std::cos(lat) * std::sin(lon),
          (rn * (1.0 - kE2) + h) * std::sin(lat)};
}

Eigen::Vector3d ecef_to_geodetic(const Eigen::Vector3d& r) {
  const double p = std::hypot(r.x(), r.y());
  const double lon = std::atan2(r.y(), r.x());
  double lat = std::atan2(r.z(), p * (1.0 - kE2));
  double h = 0.0;
  for (int i = 0; i < 6; ++i) {  // converges to < 1e-12 rad within 4 iterations
    const double rn = transverse_radius_m(lat);
    h = p / std::cos(lat) - rn;
    lat = std::atan2(r.z(), p * (1.0 - kE2 * rn / (rn + h)));
  }
  const double rn = transverse_radius_m(lat);
  h = std::abs(std::cos(lat)) > 1e-9 ? p / std::cos(lat) - rn : std::abs(r.z()) - kB;
  return {lat, lon, h};
}

Eigen::Matrix3d C_en(double lat, double lon) {
  const double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
  Eigen::Matrix3d c;
  c << -sl * co, -so, -cl * co,  //
      -sl * so, co, -cl * so,    //
      cl, 0.0, -sl;
  return c;
}

}  // namespace sinu::est::wgs84
