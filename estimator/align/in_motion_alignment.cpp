#include "estimator/align/in_motion_alignment.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "estimator/ins/rotation.hpp"

namespace sinu::est {

namespace {
// Yaw sigma when yaw has no information: uniform over (-pi, pi].
constexpr double kUniformYawSigmaRad = std::numbers::pi * std::numbers::inv_sqrt3;
// Gyro bias feedback only below this tilt sigma (RSS of north and east), and
// at most this much attitude change (bias step x window) per epoch: the
// correction of the past integrals is first order, its error the square.
constexpr double kFeedbackTiltSigmaRad = 2.0 * std::numbers::pi / 180.0;
constexpr double kFeedbackStepRad = 0.01;
// The bias estimate is carried to the next window once the fit is linear in
// yaw too (sin 20 deg = 0.98 x 20 deg); before, it depends on the yaw error.
constexpr double kCarryYawSigmaRad = 20.0 * std::numbers::pi / 180.0;

bool usable(const GnssObservation& z) {
  return z.has_position && z.has_velocity && !z.velocity_from_positions && z.v_ne_m_s.allFinite() &&
         std::isfinite(z.lat_rad) &&
         std::isfinite(z.h_m);
}
}  // namespace

void InMotionAlignment::configure(const InMotionAlignmentConfig& cfg) {
  cfg_ = cfg;
  ObaPairNoise noise;
  noise.velocity_sigma_m_s = cfg.gnss_velocity_sigma_m_s;
  noise.velocity_corr_s = cfg.gnss_velocity_corr_s;
  noise.height_sigma_m = cfg.gnss_height_sigma_m;
  noise.height_fit_s = cfg.height_fit_s;
  pairs_.configure(noise);
  reset();
}

void InMotionAlignment::reset() {
  have_prev_ = false;
  gyro_comp_rad_s_.setZero();
  const double s2 = std::max(cfg_.gyro_bias_sigma_rad_s * cfg_.gyro_bias_sigma_rad_s, 1e-12);
  bias_prior_rad_s_.setZero();
  bias_prior_cov_ = s2 * Eigen::Matrix3d::Identity();
  bias_next_rad_s_ = bias_prior_rad_s_;
  bias_next_cov_ = bias_prior_cov_;
  bias_next_t_s_ = 0.0;
  imu_broken_ = true;
  active_ = false;
  t0_s_ = t_last_gnss_s_ = 0.0;
}

void InMotionAlignment::start_window(double t_now_s) {
  // The last good estimate becomes the prior, widened by the drift since.
  const double walk2 = cfg_.gyro_bias_walk_rad_s_rt_s * cfg_.gyro_bias_walk_rad_s_rt_s;
  bias_prior_rad_s_ = bias_next_rad_s_;
  const double drift_s = bias_next_t_s_ > 0.0 ? std::max(t_now_s - bias_next_t_s_, 0.0) : 0.0;
  bias_prior_cov_ = bias_next_cov_ + walk2 * drift_s * Eigen::Matrix3d::Identity();
  body_.reset();
  pairs_.reset();
  solver_.reset();
  t0_s_ = t_now_s;
  imu_broken_ = false;
  active_ = true;
}

void InMotionAlignment::add_imu(const ImuSample& s, double dt_s) {
  // A bad sample, a gap or time running backwards breaks the window (it
  // restarts at the next epoch); otherwise the body integrals advance.
  const bool good = s.specific_force_b_m_s2.allFinite() && s.angular_rate_b_rad_s.allFinite();
  if (!good) {
    have_prev_ = false;
    imu_broken_ = true;
    return;
  }
  if (!have_prev_ || !(dt_s > 0.0 && dt_s <= cfg_.max_imu_gap_s)) {
    imu_broken_ = true;
  } else if (active_ && !imu_broken_) {
    ImuSample a = prev_, b = s;  // the fed-back bias removed from both ends
    a.angular_rate_b_rad_s -= gyro_comp_rad_s_;
    b.angular_rate_b_rad_s -= gyro_comp_rad_s_;
    body_.step(a, b, dt_s);
  }
  prev_ = s;
  have_prev_ = true;
}

bool InMotionAlignment::add_gnss(const GnssObservation& z, double t_now_s, InMotionSolution& out) {
  if (!usable(z) || !have_prev_) return false;
  if (active_ && t_now_s <= t_last_gnss_s_) return false;  // repeated or out-of-order epoch

  // Window management: (re)start on the first epoch, after a gap in either
  // stream, and when the window would exceed its cap.
  const bool restart = !active_ || imu_broken_ || t_now_s - t_last_gnss_s_ > cfg_.max_gnss_gap_s ||
                       t_now_s - t0_s_ > cfg_.max_window_s;
  if (restart) start_window(t_now_s);
  t_last_gnss_s_ = t_now_s;

  // Body side at this instant; the antenna lever arm moves to the body side:
  // v_ant = v + C_nb (w x l) makes beta = C_n0_b0 (alpha + C_b0_b (w x l)) + c.
  const Eigen::Vector3d w_b_rad_s = prev_.angular_rate_b_rad_s - gyro_comp_rad_s_;
  const Eigen::Vector3d alpha_m_s = body_.alpha_m_s() + body_.C_b0b() * w_b_rad_s.cross(cfg_.lever_arm_b_m);
  ObaVector pair;
  const ObaVector body =
      make_pair(Eigen::Vector3d::Zero(), alpha_m_s, body_.D_m(), body_.A_s(), body_.D1_m_s());
  if (pairs_.add_epoch(z, t_now_s, body, pair)) solver_.add(pair);
  const double window_s = t_now_s - t0_s_;
  if (window_s < cfg_.min_window_s) return false;

  // Fit (floors keep the weights finite for a configured zero).
  ObaNoise noise;
  noise.horizontal_var_m2_s2 = std::max(pairs_.horizontal_variance_m2_s2(), 1e-6);
  noise.vertical_var_m2_s2 = std::max(pairs_.vertical_variance_m2_s2(), 1e-6);
  noise.height_sigma_m = cfg_.gnss_height_sigma_m;
  noise.accel_bias_sigma_m_s2 = std::max(cfg_.accel_bias_sigma_m_s2, 1e-6);
  noise.gyro_bias_prior_rad_s = bias_prior_rad_s_ - gyro_comp_rad_s_;  // the prior is on the whole bias
  noise.gyro_bias_prior_cov_rad2_s2 = bias_prior_cov_;
  noise.gyro_arw_rad_rt_s = cfg_.gyro_arw_rad_rt_s;
  ObaNow now;
  now.A_s = body_.A_s();
  now.A1_s2 = body_.A1_s2();
  now.window_s = window_s;
  const Eigen::Matrix3d C_n0n = pairs_.C_n0n();
  ObaFit fit;
  if (!solver_.solve(pairs_.height_noise_gram(solver_.mean()), C_n0n.col(2), noise, now, fit)) return false;

  // Attitude now: C_nb = C_n_n0 C_n0_b0 C_b0_b, the gyro-carried C_b0_b
  // corrected for the estimated bias (it tilted it by psi = A b_g, in b0);
  // its error covariance from b0 to NED.
  const Eigen::Matrix3d C_b0b = quat_from_rotation_vector(-now.A_s * fit.gyro_bias_rad_s) * body_.C_b0b();
  const Eigen::Matrix3d C_nn0 = C_n0n.transpose();
  out.q_nb = Eigen::Quaterniond(C_nn0 * fit.C_n0b0 * C_b0b).normalized();
  const Eigen::Matrix3d R_nb0 = C_nn0 * fit.C_n0b0;
  Eigen::Matrix3d P = R_nb0 * fit.P_att_b0_rad2 * R_nb0.transpose();
  if (fit.has_null) {  // the pseudo-inverse gave that axis no variance: yaw is unknown
    P.row(2).setZero();
    P.col(2).setZero();
    P(2, 2) = kUniformYawSigmaRad * kUniformYawSigmaRad;
  }
  out.att_cov_rad2 = P;
  out.att_sigma_rad = P.diagonal().cwiseMax(0.0).cwiseSqrt();
  if (!(out.att_sigma_rad.z() < kUniformYawSigmaRad)) out.att_sigma_rad.z() = kUniformYawSigmaRad;
  out.yaw_observable = !fit.has_null && out.att_sigma_rad.z() <= cfg_.max_yaw_sigma_rad;
  out.gyro_bias_rad_s = gyro_comp_rad_s_ + fit.gyro_bias_rad_s;
  out.gyro_bias_sigma_rad_s = fit.P_gyro_bias_rad2_s2.diagonal().cwiseMax(0.0).cwiseSqrt();
  out.t_s = t_now_s;
  out.window_s = window_s;
  const bool linear = out.att_sigma_rad.head<2>().norm() <= kFeedbackTiltSigmaRad;
  if (linear && !fit.has_null && out.att_sigma_rad.z() <= kCarryYawSigmaRad) {
    bias_next_rad_s_ = out.gyro_bias_rad_s;
    bias_next_cov_ = fit.P_gyro_bias_rad2_s2;
    bias_next_t_s_ = t_now_s;
  }

  // Feed the bias back, once the fit is in its linear range (while the
  // attitude is uncertain by tens of degrees, so is the bias estimate), in
  // steps, and only the part that is known (gain I - P / s_g^2, so a
  // direction still at its prior is not moved by noise): the window
  // continues linearised about it.
  if (!linear) return true;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(fit.P_gyro_bias_rad2_s2);
  const double s2 = std::max(cfg_.gyro_bias_sigma_rad_s * cfg_.gyro_bias_sigma_rad_s, 1e-12);
  const Eigen::Vector3d gain = (Eigen::Vector3d::Ones() - eig.eigenvalues() / s2).cwiseMax(0.0);
  Eigen::Vector3d step_rad_s =
      eig.eigenvectors() * gain.asDiagonal() * eig.eigenvectors().transpose() * fit.gyro_bias_rad_s;
  const double turn_rad = step_rad_s.norm() * window_s;
  if (turn_rad > kFeedbackStepRad) step_rad_s *= kFeedbackStepRad / turn_rad;
  gyro_comp_rad_s_ += step_rad_s;
  body_.correct_gyro_bias(step_rad_s);
  pairs_.correct_gyro_bias(step_rad_s);
  solver_.correct_gyro_bias(step_rad_s);
  return true;
}

}  // namespace sinu::est
