#include "estimator/align/rest_levelling.hpp"

#include <algorithm>
#include <cmath>

#include "estimator/ins/rotation.hpp"

namespace sinu::est {

void RestLevelling::configure(const RestConfig& cfg) {
  cfg_ = cfg;
  has_estimate_ = false;
  windows_ = 0;
  restart();
}

void RestLevelling::restart() {
  now_ = snapshot_ = older_ = Sums{};
  since_snapshot_s_ = 0.0;
  have_ema_ = false;
  at_rest_ = false;
}

void RestLevelling::restore(const RestEstimate& e) {
  est_ = e;
  has_estimate_ = true;
  restart();
}

void RestLevelling::forget() {
  has_estimate_ = false;
  restart();
}

bool RestLevelling::moving(const ImuSample& s, double dt) {
  const Eigen::Vector3d& f = s.specific_force_b_m_s2;
  const Eigen::Vector3d& w = s.angular_rate_b_rad_s;
  const double a = have_ema_ ? std::min(1.0, dt / cfg_.motion_tau_s) : 1.0;
  ema_f_ += a * (f - ema_f_);
  ema_w_ += a * (w - ema_w_);
  have_ema_ = true;
  // Turning: the short-term mean rate, not single samples (a consumer gyro's
  // noise at 100 Hz alone reaches 0.08 rad/s).
  if (ema_w_.cwiseAbs().maxCoeff() > cfg_.max_rate_rad_s) return true;
  if (now_.count < 2 || now_.window_s < cfg_.motion_tau_s) return false;
  const double n = static_cast<double>(now_.count);
  const Eigen::Vector3d mean_f = now_.f / n, mean_w = now_.w / n;
  // The exponential mean of white noise of std s has std s sqrt(dt / (2 tau)).
  const double shrink = std::sqrt(std::max(dt, 1e-4) / (2.0 * cfg_.motion_tau_s));
  const Eigen::Vector3d std_f = (now_.f2 / n - mean_f.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
  const Eigen::Vector3d std_w = (now_.w2 / n - mean_w.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
  for (Eigen::Index i = 0; i < 3; ++i) {
    if (std::abs(ema_f_(i) - mean_f(i)) > cfg_.motion_accel_m_s2 + 4.0 * shrink * std_f(i)) return true;
    if (std::abs(ema_w_(i) - mean_w(i)) > cfg_.motion_rate_rad_s + 4.0 * shrink * std_w(i)) return true;
  }
  return false;
}

void RestLevelling::add(const ImuSample& s, double dt) {
  const Eigen::Vector3d& f = s.specific_force_b_m_s2;
  const Eigen::Vector3d& w = s.angular_rate_b_rad_s;
  if (!f.allFinite() || !w.allFinite()) return;
  if (moving(s, dt)) {
    // Keep the window as it was before the onset reached the samples.
    if (at_rest_ && older_.window_s >= cfg_.window_s) estimate_from(older_);
    restart();
    return;
  }
  now_.f += f;
  now_.f2 += f.cwiseAbs2();
  now_.w += w;
  now_.w2 += w.cwiseAbs2();
  now_.temp += s.has_temp ? s.temp_degC : 0.0;
  if (s.has_mag && s.mag_b_uT.allFinite()) {
    now_.m += s.mag_b_uT;
    ++now_.count_m;
  }
  ++now_.count;
  now_.window_s += dt;
  since_snapshot_s_ += dt;
  if (since_snapshot_s_ >= cfg_.motion_tau_s) {
    older_ = snapshot_;
    snapshot_ = now_;
    since_snapshot_s_ = 0.0;
  }
  if (now_.window_s < cfg_.window_s) return;
  const double n = static_cast<double>(now_.count);
  const Eigen::Vector3d var_f = now_.f2 / n - (now_.f / n).cwiseAbs2();
  if (var_f.maxCoeff() > cfg_.max_accel_std_m_s2 * cfg_.max_accel_std_m_s2) {
    restart();
    return;
  }
  if (!at_rest_) ++windows_;
  at_rest_ = true;
  estimate_from(now_);
}

void RestLevelling::estimate_from(const Sums& sums) {
  const double n = static_cast<double>(sums.count);
  RestEstimate& e = est_;
  e.mean_specific_force_b_m_s2 = sums.f / n;
  const Eigen::Vector3d& f = e.mean_specific_force_b_m_s2;
  const Eigen::Vector3d var_f = sums.f2 / n - f.cwiseAbs2();
  e.specific_force_sigma_m_s2 = std::sqrt(std::max(var_f.maxCoeff(), 0.0) / n);
  // At rest f_b = -C_bn g_n: roll = atan2(-fy, -fz), pitch = atan2(fx, sqrt(fy^2 + fz^2)).
  e.q_level = quat_from_euler(std::atan2(-f.y(), -f.z()), std::atan2(f.x(), std::hypot(f.y(), f.z())), 0.0);
  e.mean_rate_b_rad_s = sums.w / n;
  // Standard error of the mean, white-noise assumption; floor 1e-5 rad/s
  // (2 deg/h) for correlated noise the window cannot see.
  const double var_w = (sums.w2 / n - e.mean_rate_b_rad_s.cwiseAbs2()).maxCoeff();
  e.mean_rate_sigma_rad_s = std::sqrt(std::max(var_w, 0.0) / n + 1e-10);
  e.has_mag = sums.count_m > 0;
  if (e.has_mag) e.mean_mag_b_uT = sums.m / static_cast<double>(sums.count_m);
  e.temp_degC = sums.temp / n;
  e.duration_s = sums.window_s;
  has_estimate_ = true;
}

}  // namespace sinu::est
