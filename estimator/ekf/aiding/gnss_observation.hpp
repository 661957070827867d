#pragma once
// One GNSS epoch as the estimator sees it (the firmware converts a driver
// GpsFix into this). Position of the antenna, horizontal velocity, course.
#include <Eigen/Core>
#include <cmath>

namespace sinu::est {

struct GnssObservation {
  double arrival_s = 0.0;   // board time the epoch arrived
  bool has_position = false;
  double lat_rad = 0.0, lon_rad = 0.0, h_m = 0.0;  // antenna, WGS-84 ellipsoidal
  bool has_height = true;  // false: a horizontal fix (RMC or GLL without GGA), h_m NaN
  Eigen::Vector3d sigma_ned_m = Eigen::Vector3d::Constant(3.0);
  bool sigma_is_guess = false;  // not the receiver's statement (no GST: DOP x UERE): the navigator rescales it
  bool has_velocity = false;
  Eigen::Vector2d v_ne_m_s = Eigen::Vector2d::Zero();
  double sigma_vel_m_s = 0.3;
  bool velocity_from_positions = false;  // not the receiver's: differenced fixes (align/position_velocity.hpp)
  bool course_held = false;  // the receiver held its course at low speed (nav/course_hold.hpp): a speed, no direction
  double decimal_year = NAN;  // UTC date of the fix when the receiver sent one (RMC, ZDA): the geomagnetic model's epoch
};

}  // namespace sinu::est
