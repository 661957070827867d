#pragma once
// The INS's velocity change over the last second, from the strapdown steps
// alone (the filter's corrections left out: a correction is not motion), for
// a GNSS velocity older than its fix: the receiver reports v(t - tau), which
// is v(t) minus the mean acceleration over [t - tau, t] times tau. A smoothed
// acceleration lags by its own time constant (0.2 s), and through a turn's
// entry or a stop the prediction then misses by tau x 0.2 s x the jerk:
// 0.05 m/s at a roll-in, as much as the velocity's noise, which a vertical
// lever arm (roll rate x l_z) took up in the simulated flights.
#include <Eigen/Core>
#include <algorithm>

#include "estimator/util/ring_buffer.hpp"

namespace sinu::est {

class VelocityHistory {
 public:
  static constexpr double kStep_s = 0.005;  // kept every 5 ms: 1 s in 200 entries at any IMU rate

  void clear() {
    samples_.clear();
    sum_n_m_s_.setZero();
    latest_t_s_ = 0.0;
  }
  /// One strapdown step ending at t_s, which changed the velocity by dv_n.
  void add(double t_s, const Eigen::Vector3d& dv_n_m_s) {
    sum_n_m_s_ += dv_n_m_s;
    latest_t_s_ = t_s;
    if (!samples_.empty() && t_s - samples_.back().t_s < kStep_s) return;
    if (samples_.full()) samples_.pop();
    samples_.push({t_s, sum_n_m_s_});
  }
  /// The mean acceleration over [t_end_s - span_s, t_end_s]; false (and
  /// accel_n untouched) when the history does not cover it.
  bool mean_accel(double t_end_s, double span_s, Eigen::Vector3d& accel_n_m_s2) const {
    Eigen::Vector3d u_end, u_start;
    if (span_s <= 0.0 || !at(t_end_s, u_end) || !at(t_end_s - span_s, u_start)) return false;
    accel_n_m_s2 = (u_end - u_start) / span_s;
    return true;
  }

 private:
  struct Sample {
    double t_s;
    Eigen::Vector3d sum_n_m_s;  // the velocity changes added up to t_s
  };
  /// Sample i of the kept ones, then the latest step (kept or not) as the last.
  Sample point(std::size_t i) const { return i < samples_.size() ? samples_[i] : Sample{latest_t_s_, sum_n_m_s_}; }
  bool at(double t_s, Eigen::Vector3d& u) const {
    const std::size_t n = samples_.size() + 1;
    if (samples_.empty() || t_s < samples_[0].t_s || t_s > latest_t_s_ + 1e-9) return false;
    std::size_t i = n - 1;
    while (i > 1 && point(i - 1).t_s > t_s) --i;  // the newest pair around t_s (a fix is near the end)
    const Sample a = point(i - 1), b = point(i);
    const double w = b.t_s > a.t_s ? std::clamp((t_s - a.t_s) / (b.t_s - a.t_s), 0.0, 1.0) : 1.0;
    u = a.sum_n_m_s + w * (b.sum_n_m_s - a.sum_n_m_s);
    return true;
  }

  RingBuffer<Sample, 200> samples_;
  Eigen::Vector3d sum_n_m_s_ = Eigen::Vector3d::Zero();
  double latest_t_s_ = 0.0;
};

}  // namespace sinu::est
