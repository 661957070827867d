#pragma once
// The navigation solution of the strapdown INS: attitude of body FRD w.r.t.
// NED as a unit quaternion q_nb (v_n = q_nb * v_b), NED velocity, and
// WGS-84 geodetic position.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "estimator/earth/wgs84.hpp"

namespace sinu::est {

struct NavState {
  double t_s = 0.0;
  Eigen::Quaterniond q_nb = Eigen::Quaterniond::Identity();
  Eigen::Vector3d v_n_m_s = Eigen::Vector3d::Zero();
  double lat_rad = 0.0;
  double lon_rad = 0.0;
  double h_m = 0.0;

  Eigen::Matrix3d C_nb() const { return q_nb.toRotationMatrix(); }
  /// Moves the position by d_ned_m (north, east, down metres, small against the Earth's radii).
  void move_position_m(const Eigen::Vector3d& d_ned_m) {
    const double rm = wgs84::meridian_radius_m(lat_rad) + h_m;
    const double rn = wgs84::transverse_radius_m(lat_rad) + h_m;
    lat_rad += d_ned_m.x() / rm;
    lon_rad = wgs84::wrap_lon_rad(lon_rad + d_ned_m.y() / (rn * std::cos(lat_rad)));
    h_m -= d_ned_m.z();
  }
};

}  // namespace sinu::est
