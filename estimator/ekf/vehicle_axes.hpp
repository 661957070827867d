#pragma once
// The vehicle's lateral (right) and vertical (down) axes in the unit's body
// frame: y and z as the dataset contract mounts the unit (x forward), or as
// the vehicle detector finds them for a unit on a bracket. The
// non-holonomic constraint acts along them; the vehicle_mount state turns
// them about the vertical.
#include <algorithm>
#include <cmath>
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sinu::est {

struct VehicleAxes {
  Eigen::Vector3d lateral_b = Eigen::Vector3d::UnitY();
  Eigen::Vector3d vertical_b = Eigen::Vector3d::UnitZ();
  /// The vehicle's forward axis in the body frame.
  Eigen::Vector3d forward_b() const { return lateral_b.cross(vertical_b); }
  /// The axes of the unit turned `yaw_rad` further (to the right) on the vehicle: they turn the other way about the
  /// vertical in the body frame.
  VehicleAxes turned(double yaw_rad) const {
    return {Eigen::AngleAxisd(-yaw_rad, vertical_b) * lateral_b, vertical_b};
  }
  /// The unit's roll, pitch and yaw on the vehicle [rad]: ZYX angles of the body w.r.t. the vehicle's
  /// forward-right-down axes (a unit turned 45 deg right on its bracket: yaw +45 deg).
  Eigen::Vector3d unit_euler_rad() const {
    const Eigen::Vector3d f = forward_b();
    return {std::atan2(vertical_b.y(), vertical_b.z()), -std::asin(std::clamp(vertical_b.x(), -1.0, 1.0)),
            std::atan2(lateral_b.x(), f.x())};
  }
};

}  // namespace sinu::est
