#include "estimator/align/coarse_alignment.hpp"

#include <algorithm>
#include <cmath>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

void CoarseAlignment::reset_window() {
  sum_f_.setZero();
  sum_f2_.setZero();
  sum_w_.setZero();
  sum_w2_.setZero();
  max_w_.setZero();
  sum_m_.setZero();
  count_m_ = 0;
  window_s_ = 0.0;
  sum_temp_ = 0.0;
  count_ = 0;
}

void CoarseAlignment::add_imu(const ImuSample& s, double dt) {
  if (status_ == AlignStatus::WaitingForRest) {
    const Eigen::Vector3d& f = s.specific_force_b_m_s2;
    const Eigen::Vector3d& w = s.angular_rate_b_rad_s;
    if (!f.allFinite() || !w.allFinite()) return;
    if (w.cwiseAbs().maxCoeff() > cfg_.max_rate_rad_s) {
      reset_window();
      return;
    }
    sum_f_ += f;
    sum_f2_ += f.cwiseAbs2();
    sum_w_ += w;
    sum_w2_ += w.cwiseAbs2();
    sum_temp_ += s.has_temp ? s.temp_degC : 0.0;
    if (s.has_mag && s.mag_b_uT.allFinite()) {
      sum_m_ += s.mag_b_uT;
      ++count_m_;
    }
    ++count_;
    window_s_ += dt;
    if (window_s_ < cfg_.level_window_s) return;
    const double n = static_cast<double>(count_);
    const Eigen::Vector3d mean_f = sum_f_ / n;
    const Eigen::Vector3d var_f = sum_f2_ / n - mean_f.cwiseAbs2();
    if (var_f.maxCoeff() > cfg_.max_accel_std_m_s2 * cfg_.max_accel_std_m_s2) {
      reset_window();
      return;
    }
    // At rest f_b = -C_bn g_n: roll = atan2(-fy, -fz), pitch = atan2(fx, sqrt(fy^2 + fz^2)).
    const double roll = std::atan2(-mean_f.y(), -mean_f.z());
    const double pitch = std::atan2(mean_f.x(), std::hypot(mean_f.y(), mean_f.z()));
    q_level_ = quat_from_euler(roll, pitch, 0.0);
    q_now_ = q_level_;
    mean_rate_ = sum_w_ / n;
    // Standard error of the mean, white-noise assumption; floor 1e-5 rad/s
    // (2 deg/h) for correlated noise the window cannot see.
    const double var_w = (sum_w2_ / n - mean_rate_.cwiseAbs2()).maxCoeff();
    mean_rate_sigma_ = std::sqrt(std::max(var_w, 0.0) / n + 1e-10);
    temp_ref_ = sum_temp_ / n;
    // Magnetic heading: the field in the levelled (yaw 0) frame is Rz(-yaw) F_n,
    // whose horizontal angle is declination - yaw.
    have_mag_heading_ = cfg_.mag_heading && count_m_ > 0;
    if (have_mag_heading_) {
      const Eigen::Vector3d m_level = q_level_ * (sum_m_ / static_cast<double>(count_m_));
      mag_heading_rad_ = cfg_.mag_declination_rad - std::atan2(m_level.y(), m_level.x());
    }
    status_ = AlignStatus::Levelled;
    return;
  }
  if (status_ == AlignStatus::Levelled) {
    q_now_ = (q_now_ * quat_from_rotation_vector((s.angular_rate_b_rad_s - mean_rate_) * dt)).normalized();
  }
}

bool CoarseAlignment::add_gnss(const GnssObservation& z, double t_now, AlignmentResult& out) {
  if (status_ != AlignStatus::Levelled || !z.has_position) return false;
  double turn = 0.0;  // about down, taking the gyro-carried attitude to the true heading
  if (have_mag_heading_) {
    turn = mag_heading_rad_;  // q_now_ started from q_level_ (yaw 0) at rest
  } else {
    if (!z.has_velocity || z.v_ne_m_s.norm() < cfg_.min_course_speed_m_s) return false;
    turn = std::atan2(z.v_ne_m_s.y(), z.v_ne_m_s.x()) - euler_from_quat(q_now_).z();
  }
  const Eigen::Quaterniond rot_down(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()));
  // The rest attitude now has a heading too: remove Earth rate from the turn-on bias.
  const Eigen::Quaterniond q_rest = rot_down * q_level_;
  out.gyro_bias_sigma_rad_s = mean_rate_sigma_;
  out.gyro_bias_rad_s = mean_rate_ - q_rest.conjugate() * wgs84::omega_ie_n(z.lat_rad);
  out.nav.q_nb = (rot_down * q_now_).normalized();
  out.nav.v_n_m_s = z.has_velocity ? Eigen::Vector3d(z.v_ne_m_s.x(), z.v_ne_m_s.y(), 0.0) : Eigen::Vector3d::Zero();
  out.nav.lat_rad = z.lat_rad;
  out.nav.lon_rad = z.lon_rad;
  out.nav.h_m = z.h_m;
  out.nav.t_s = t_now;
  out.temp_ref_degC = temp_ref_;
  status_ = AlignStatus::Aligned;
  return true;
}

}  // namespace sinu::est
