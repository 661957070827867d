#pragma once
// An attitude estimate updated with one magnetometer sample's heading: the
// field rotated to NED, C_nb m_b, has the declination as its horizontal angle.
//
// Why the attitude, not only the yaw: in a steady acceleration (a straight
// speed change, a constant turn) the in-motion alignment sees one direction,
// the specific force's, so its attitude is unknown about that axis, which
// leans off the vertical by atan(a / g). Its covariance then spans that
// axis: a yaw error comes with a tilt error a / g times it (fixed wing at
// 0.5 m/s^2: tilt sigma 0.1-0.3 rad for 8 s). The heading fixes the rotation
// about that axis, and with it the tilt (docs/in_motion_alignment.md).
//
// Model: phi the attitude error in NED (C_hat = (I - [phi x]) C, the EKF's
// att state), prior N(0, P); h(phi) = angle(R(phi) C_hat m_b) - declination
// = 0 + v, v ~ N(0, heading_sigma^2). With m = C_hat m_b, dm = phi x m, so
// dh/dphi = [-m_d m_n, -m_d m_e, m_n^2 + m_e^2] / (m_n^2 + m_e^2): the
// vertical field turns a tilt error into heading. Iterated (Gauss-Newton on
// the posterior), as the prior's weak axis may hold any angle.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sinu::est {

/// Updates q_nb and its covariance P_rad2 (phi in NED) in place. False, and
/// nothing changed, when the field has no horizontal part to speak of or the
/// heading contradicts the prior beyond 3 sigma.
bool update_with_field_heading(Eigen::Quaterniond& q_nb, Eigen::Matrix3d& P_rad2, const Eigen::Vector3d& mag_b_uT,
                               double declination_rad, double heading_sigma_rad);

}  // namespace sinu::est
