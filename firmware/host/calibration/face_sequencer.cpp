#include "firmware/host/calibration/face_sequencer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "firmware/host/calibration/bench_positions.hpp"
#include "firmware/host/calibration/still_segments.hpp"

namespace sinu::calibration {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) / kDeg;
}
}  // namespace

FaceSequencer::FaceSequencer(std::size_t positions, const FaceSequencerConfig& config)
    : positions_(std::min(positions, kMaxPositions)), cfg_(config) {
  faces_.reserve(positions_);
}

bool FaceSequencer::is_held(const Eigen::Vector3d& up) const {
  return std::any_of(faces_.begin(), faces_.end(),
                     [&](const HeldFace& f) { return angle_deg(f.up_b, up) < cfg_.same_attitude_deg; });
}

std::size_t FaceSequencer::next() const {
  for (std::size_t k = 0; k < positions_; ++k)
    if (!is_held(position_up_b(k))) return k;
  return positions_ > 0 ? positions_ - 1 : 0;
}

FaceEvent FaceSequencer::add(double t, const std::array<double, 3>& f, const std::array<double, 3>& w) {
  if (!started_) {
    started_ = true;
    window_start_ = t;
  }
  FaceEvent e = FaceEvent::None;
  if (t - window_start_ >= cfg_.window_s && n_ > 0.0) e = close_window(t);
  const Eigen::Vector3d fv(f[0], f[1], f[2]), wv(w[0], w[1], w[2]);
  f_sum_ += fv;
  w_sum_ += wv;
  f_sq_ += fv.cwiseAbs2();
  w_sq_ += wv.cwiseAbs2();
  n_ += 1.0;
  last_t_ = t;
  return e;
}

FaceEvent FaceSequencer::close_window(double t) {
  const Eigen::Vector3d f = f_sum_ / n_, w = w_sum_ / n_;
  const double f_var = (f_sq_ / n_ - f.cwiseAbs2()).cwiseMax(0.0).sum();
  const double w_var = (w_sq_ / n_ - w.cwiseAbs2()).cwiseMax(0.0).sum();
  const double start = window_start_;
  f_sum_.setZero();
  w_sum_.setZero();
  f_sq_.setZero();
  w_sq_.setZero();
  n_ = 0.0;
  window_start_ = t;
  const bool quiet = f_var <= cfg_.accel_std_limit_m_s2 * cfg_.accel_std_limit_m_s2 &&
                     w_var <= cfg_.gyro_std_limit_rad_s * cfg_.gyro_std_limit_rad_s;
  const bool steady = have_prev_ && angle_deg(f, prev_f_) <= cfg_.tilt_limit_deg &&
                      (w - prev_w_).norm() <= cfg_.rate_change_limit_deg_s * kDeg;
  prev_f_ = f;
  prev_w_ = w;
  have_prev_ = true;
  const bool still = quiet && steady;
  if (finished()) return FaceEvent::None;
  if (holding_) {
    if (!still || angle_deg(f, hold_f_) > cfg_.tilt_limit_deg) {
      holding_ = false;
      return FaceEvent::Moved;
    }
    if (t - hold_start_s_ >= cfg_.hold_s) {
      holding_ = false;
      faces_.push_back({next(), attitude_, hold_f_.normalized(), hold_start_s_, t});
      said_already_ = true;  // still there: the next prompt says to turn it
      return FaceEvent::Held;
    }
    return FaceEvent::None;
  }
  if (!still) {
    said_already_ = false;
    return FaceEvent::None;
  }
  attitude_ = attitude_name(f);
  if (is_held(f)) {
    if (said_already_) return FaceEvent::None;
    said_already_ = true;
    return FaceEvent::AlreadyHeld;
  }
  holding_ = true;
  hold_start_s_ = start;
  hold_f_ = f;
  return FaceEvent::HoldStarted;
}

}  // namespace sinu::calibration
