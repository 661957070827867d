#include "estimator/align/coarse_alignment.hpp"

#include <algorithm>
#include <cmath>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

void CoarseAlignment::configure(const AlignmentConfig& cfg) {
  cfg_ = cfg;
  rest_.configure(cfg.rest);
  status_ = AlignStatus::WaitingForRest;
  q_now_ = Eigen::Quaterniond::Identity();
  carried_s_ = 0.0;
}

void CoarseAlignment::add_imu(const ImuSample& s, double dt) {
  if (status_ == AlignStatus::Aligned) return;
  rest_.add(s, dt);
  if (!rest_.has_estimate()) return;
  status_ = AlignStatus::Levelled;
  if (rest_.at_rest()) {  // still at rest: the levelling itself is the attitude
    q_now_ = rest_.estimate().q_level;
    carried_s_ = 0.0;
    return;
  }
  const Eigen::Vector3d w = s.angular_rate_b_rad_s - rest_.estimate().mean_rate_b_rad_s;
  q_now_ = (q_now_ * quat_from_rotation_vector(w * dt)).normalized();
  carried_s_ += dt;
}

bool CoarseAlignment::add_gnss(const GnssObservation& z, double t_now, AlignmentResult& out) {
  if (status_ != AlignStatus::Levelled || !z.has_position) return false;
  const RestEstimate& r = rest_.estimate();
  // Magnetic heading: the field in the levelled (yaw 0) frame is Rz(-yaw) F_n,
  // whose horizontal angle is declination - yaw.
  if (cfg_.use_mag && r.has_mag) {
    const Eigen::Vector3d m_level = r.q_level * r.mean_mag_b_uT;
    const double declination = cfg_.declination_known ? cfg_.mag_declination_rad : 0.0;
    const double heading = declination - std::atan2(m_level.y(), m_level.x());
    finish(z, t_now, heading,
           cfg_.declination_known ? cfg_.mag_heading_sigma_rad : cfg_.mag_unknown_declination_sigma_rad, out);
    return true;
  }
  if (!z.has_velocity || z.v_ne_m_s.norm() < cfg_.min_course_speed_m_s) return false;
  const double turn = std::atan2(z.v_ne_m_s.y(), z.v_ne_m_s.x()) - euler_from_quat(q_now_).z();
  finish(z, t_now, turn, cfg_.course_heading_sigma_rad, out);
  return true;
}

void CoarseAlignment::finish(const GnssObservation& z, double t_now, double turn, double yaw_sigma,
                             AlignmentResult& out) {
  const RestEstimate& r = rest_.estimate();
  const Eigen::Quaterniond rot_down(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()));
  // The rest attitude now has a heading too: remove Earth rate from the turn-on bias.
  const Eigen::Quaterniond q_rest = rot_down * r.q_level;
  out.at_rest = true;
  out.rest_specific_force_b_m_s2 = r.mean_specific_force_b_m_s2;
  out.rest_specific_force_sigma_m_s2 = r.specific_force_sigma_m_s2;
  out.gyro_bias_sigma_rad_s = r.mean_rate_sigma_rad_s;
  out.gyro_bias_rad_s = r.mean_rate_b_rad_s - q_rest.conjugate() * wgs84::omega_ie_n(z.lat_rad);
  // Tilt: the levelling's own noise plus what the gyros added since the rest.
  const double carried = r.mean_rate_sigma_rad_s * carried_s_;
  const double tilt = std::sqrt(2e-3 * 2e-3 + carried * carried);
  out.att_sigma_rad = {tilt, tilt, yaw_sigma};
  out.nav.q_nb = (rot_down * q_now_).normalized();
  out.nav.v_n_m_s = z.has_velocity ? Eigen::Vector3d(z.v_ne_m_s.x(), z.v_ne_m_s.y(), 0.0) : Eigen::Vector3d::Zero();
  out.nav.lat_rad = z.lat_rad;
  out.nav.lon_rad = z.lon_rad;
  out.nav.h_m = z.h_m;
  out.nav.t_s = t_now;
  out.temp_ref_degC = r.temp_degC;
  status_ = AlignStatus::Aligned;
}

}  // namespace sinu::est
