#pragma once
// What the navigation unit hands to its outputs (MAVLink, NMEA, the log) once
// per output period: the solution, its covariance and its health, with the
// time references an external receiver's messages need.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>

namespace sinu::board {

struct NavSolution {
  double t_s = 0.0;                 // board monotonic time of the solution [s]
  bool has_utc = false;             // UTC known (from the GNSS time of the last fix)
  std::int64_t utc_ms = 0;          // UTC of the solution, ms since 1970-01-01 (valid when has_utc)
  bool aligned = false;             // a solution exists; everything below is meaningless otherwise
  double lat_deg = 0.0, lon_deg = 0.0;  // WGS-84, of the IMU
  double h_ellipsoid_m = 0.0;       // WGS-84 ellipsoidal height
  double geoid_sep_m = 0.0;         // geoid above the ellipsoid (the receiver's, from GGA; 0 if unknown)
  Eigen::Vector3d v_ned_m_s = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_nb = Eigen::Quaterniond::Identity();  // body FRD -> NED
  Eigen::Vector3d angular_rate_b_rad_s = Eigen::Vector3d::Zero();  // compensated, body FRD
  // Covariance of (position NED [m], velocity NED [m/s], attitude error [rad],
  // C_nb_hat = (I - [phi x]) C_nb, NED), as the EKF holds it.
  Eigen::Matrix<double, 9, 9> P_nav = Eigen::Matrix<double, 9, 9>::Identity();
  std::uint32_t flags = 0;          // estimator nav_flag bits (estimator/nav/nav_health.hpp)
  int satellites = 0;               // of the last GNSS fix (0 if none)
  double hdop = 99.99;              // of the last GNSS fix
};

}  // namespace sinu::board
