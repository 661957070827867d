#pragma once
// The vertical channel against the GNSS heights. No common receiver reports a
// vertical velocity (RMC and VTG are horizontal), so the INS's vd is seen only
// through the heights; a shift of the accelerometer's bias along gravity (a
// knock, a clipping burst, vibration that changes with the throttle) that the
// calibrated model says cannot happen is then taken by the height (each fix
// pulls it back, the receiver's correlated error takes the rest) while vd
// runs away: 0.3 m/s^2 left vd 14 m/s wrong for minutes with a claimed sigma
// of 0.2 m/s and every fix accepted. PX4 EKF2 watches the same
// (bad_acc_vertical: its vertical innovations one-signed) and then lets the
// accelerometer bias move fast.
//
// The check: over the last `window_s` of fixes, the heights' least-squares
// rate against the mean of the INS's vd at the same fixes. It fires when they
// disagree by more than `min_disagreement_m_s` and `sigmas` times the
// combined sigma for `persist_s`, and only when the heights lie on a line (the
// fit's residual RMS within `line_residual_factor` and its largest within
// `line_max_residual_factor` of the fix-to-fix scatter): a receiver's height
// step is no rate.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace sinu::est {

struct VerticalCheckConfig {
  double window_s = 8.0;
  std::size_t min_fixes = 6;  // a 1-Hz receiver too
  double min_span_s = 2.0;
  double min_disagreement_m_s = 1.0;
  double sigmas = 5.0;
  double persist_s = 2.0;
  double line_residual_factor = 2.5;
  double line_max_residual_factor = 4.0;
  double scatter_floor_m = 0.05;  // heights printed to 1 cm, a receiver's smoothing
};

/// The heights' rate where the check fired: the vertical velocity to reset to.
struct VerticalRate {
  double vd_m_s = 0.0;     // down
  double sigma_m_s = 0.0;
  double disagreement_m_s = 0.0;  // INS vd - the heights' vd
};

class VerticalCheck {
 public:
  void configure(const VerticalCheckConfig& cfg) {
    cfg_ = cfg;
    restart();
  }
  /// Forget every fix (after a reset, an outage).
  void restart() {
    n_ = 0;
    disagree_since_s_ = kNever;
  }
  /// A fix's height [m, up] valid at t, and the INS's vd [m/s, down] and its
  /// sigma then. True when the vertical channel has run away (`out` is set).
  bool push(double t_s, double h_m, double vd_ins_m_s, double sigma_vd_m_s, VerticalRate& out);

 private:
  static constexpr std::size_t kMax = 96;  // 8 s of 10-Hz fixes, with room
  static constexpr double kNever = -1e300;
  struct Fix {
    double t_s, h_m, vd_ins_m_s;
  };
  VerticalCheckConfig cfg_;
  std::array<Fix, kMax> fix_{};
  std::size_t n_ = 0;
  double disagree_since_s_ = kNever;
};

inline bool VerticalCheck::push(double t_s, double h_m, double vd_ins_m_s, double sigma_vd_m_s, VerticalRate& out) {
  if (!std::isfinite(t_s) || !std::isfinite(h_m) || !std::isfinite(vd_ins_m_s)) return false;
  if (n_ > 0 && t_s <= fix_[n_ - 1].t_s) restart();  // time went back: start over
  // Keep the window (and never more than kMax fixes).
  std::size_t drop = 0;
  while (drop < n_ && (t_s - fix_[drop].t_s > cfg_.window_s || n_ - drop >= kMax)) ++drop;
  if (drop > 0) {
    std::copy(fix_.begin() + static_cast<std::ptrdiff_t>(drop), fix_.begin() + static_cast<std::ptrdiff_t>(n_),
              fix_.begin());
    n_ -= drop;
  }
  fix_[n_++] = {t_s, h_m, vd_ins_m_s};
  if (n_ < cfg_.min_fixes || fix_[n_ - 1].t_s - fix_[0].t_s < cfg_.min_span_s) {
    disagree_since_s_ = kNever;
    return false;
  }
  // Least-squares line through the heights; the INS's mean vd.
  double t_mean = 0.0, h_mean = 0.0, vd_mean = 0.0;
  for (std::size_t k = 0; k < n_; ++k) {
    t_mean += fix_[k].t_s;
    h_mean += fix_[k].h_m;
    vd_mean += fix_[k].vd_ins_m_s;
  }
  const double n = static_cast<double>(n_);
  t_mean /= n;
  h_mean /= n;
  vd_mean /= n;
  double stt = 0.0, sth = 0.0;
  for (std::size_t k = 0; k < n_; ++k) {
    const double dt = fix_[k].t_s - t_mean;
    stt += dt * dt;
    sth += dt * (fix_[k].h_m - h_mean);
  }
  const double rate_up = sth / stt;
  double residual2 = 0.0, residual_max = 0.0, r_prev = 0.0;
  std::array<double, kMax> step{};  // fix-to-fix scatter about the line: a height step moves one of them
  for (std::size_t k = 0; k < n_; ++k) {
    const double r = fix_[k].h_m - h_mean - rate_up * (fix_[k].t_s - t_mean);
    residual2 += r * r;
    residual_max = std::max(residual_max, std::abs(r));
    if (k > 0) step[k - 1] = std::abs(r - r_prev);
    r_prev = r;
  }
  const std::size_t m = n_ - 1;
  std::nth_element(step.begin(), step.begin() + static_cast<std::ptrdiff_t>(m / 2),
                   step.begin() + static_cast<std::ptrdiff_t>(m));
  // A white height error sigma gives fix-to-fix differences of median 0.954 sigma.
  const double scatter_m = std::max(cfg_.scatter_floor_m, step[m / 2] / 0.954);
  const double residual_m = std::sqrt(residual2 / std::max(1.0, n - 2.0));
  // On a line: the residuals as the scatter says, none beyond 4 of it (a
  // step near the window's edge hides in the RMS, not in the largest).
  const bool on_a_line = residual_m <= cfg_.line_residual_factor * scatter_m &&
                         residual_max <= cfg_.line_max_residual_factor * scatter_m;
  const double sigma_rate = std::max(residual_m, scatter_m) / std::sqrt(stt);
  const double disagreement = vd_mean + rate_up;  // vd is down, the rate up
  const double limit = std::max(cfg_.min_disagreement_m_s, cfg_.sigmas * std::hypot(sigma_rate, sigma_vd_m_s));
  if (!on_a_line || std::abs(disagreement) <= limit) {
    disagree_since_s_ = kNever;
    return false;
  }
  if (disagree_since_s_ == kNever) disagree_since_s_ = t_s;
  if (t_s - disagree_since_s_ < cfg_.persist_s) return false;
  out.vd_m_s = -rate_up;
  out.sigma_m_s = sigma_rate;
  out.disagreement_m_s = disagreement;
  restart();
  return true;
}

}  // namespace sinu::est
