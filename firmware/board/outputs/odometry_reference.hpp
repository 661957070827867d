#pragma once
// What ODOMETRY needs beyond one solution: the local NED origin (fixed at the
// first aligned solution, never moved) and the estimate-reset counter.
//
// Local position: curvilinear NED from the origin with the WGS-84 radii of
// curvature at the mean latitude, north = dlat (R_M + h), east = dlon (R_N + h)
// cos(lat), down = h_origin - h. Heights are kept as heights (as PX4 and
// ArduPilot do for their local frames) rather than projected on the tangent
// plane, which would drop below the vehicle by d^2 / 2R (8 m at 10 km).
#include <Eigen/Core>
#include <cstdint>

#include "firmware/board/nav_solution.hpp"

namespace sinu::board {

class OdometryReference {
 public:
  /// Feed every solution the output sees (in order), sent or not: the origin
  /// is fixed at the first aligned one, and every solution whose flags carry a
  /// position, velocity or yaw reset event increments the reset counter.
  void observe(const NavSolution& sol);
  bool has_origin() const { return has_origin_; }
  /// Position of `sol` in the local NED frame [m] (zero before the origin).
  Eigen::Vector3d local_ned_m(const NavSolution& sol) const;
  /// Wraps at 256, as the uint8 field does.
  std::uint8_t reset_counter() const { return reset_counter_; }

 private:
  bool has_origin_ = false;
  double lat0_rad_ = 0.0, lon0_rad_ = 0.0, h0_m_ = 0.0;
  std::uint8_t reset_counter_ = 0;
};

}  // namespace sinu::board
