#pragma once
// One IMU sample at instant t: the sensor output at that instant (dataset
// contract: not an increment). Body frame FRD.
#include <cstdint>
#include <Eigen/Core>

namespace sinu::est {

struct ImuSample {
  double t_s = 0.0;
  Eigen::Vector3d specific_force_b_m_s2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_rate_b_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d mag_b_uT = Eigen::Vector3d::Zero();  // magnetic flux density, body FRD [uT]
  double temp_degC = 0.0;
  bool has_mag = false;
  bool has_temp = false;
  std::uint8_t clipped_axes = 0;  // bit a: axis a (ax ay az gx gy gz) at full scale, set by the navigator's screen
  std::uint8_t clip_reach_axes = 0;  // bit a: a clipped input of axis a within the prefilter's reach of this instant
};

}  // namespace sinu::est
