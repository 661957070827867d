#pragma once
// The navigation solution of the strapdown INS: attitude of body FRD w.r.t.
// NED as a unit quaternion q_nb (v_n = q_nb * v_b), NED velocity, and
// WGS-84 geodetic position.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sinu::est {

struct NavState {
  double t_s = 0.0;
  Eigen::Quaterniond q_nb = Eigen::Quaterniond::Identity();
  Eigen::Vector3d v_n_m_s = Eigen::Vector3d::Zero();
  double lat_rad = 0.0;
  double lon_rad = 0.0;
  double h_m = 0.0;

  Eigen::Matrix3d C_nb() const { return q_nb.toRotationMatrix(); }
};

}  // namespace sinu::est
