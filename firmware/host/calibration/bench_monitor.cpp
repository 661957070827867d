#include "firmware/host/calibration/bench_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sinu::calibration {

namespace {
constexpr double kRadToDeg = 180.0 / std::numbers::pi;

double norm(const std::array<double, 3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
}  // namespace

const char* bench_event_name(BenchEvent e) { return e == BenchEvent::Moved ? "moved" : "temperature_step"; }

BenchMonitor::BenchMonitor(const BenchMonitorConfig& config) : cfg_(config) { marks_.reserve(64); }

bool BenchMonitor::mark(BenchEvent e, double start_s, double end_s, double size) {
  // A window right after the same kind of mark extends it (one move, one mark).
  for (auto it = marks_.rbegin(); it != marks_.rend(); ++it) {
    if (it->event != e) continue;
    if (start_s <= it->end_s + 1e-9) {
      it->end_s = std::max(it->end_s, end_s);
      it->size = std::max(it->size, size);
      return false;
    }
    break;
  }
  marks_.push_back({e, start_s, end_s, size});
  return true;
}

bool BenchMonitor::close_motion_window(double t_s) {
  std::array<double, 3> f{}, w{};
  for (std::size_t i = 0; i < 3; ++i) {
    f[i] = f_sum_[i] / n_;
    w[i] = w_sum_[i] / n_;
  }
  const double start = window_start_;
  f_sum_ = {};
  w_sum_ = {};
  n_ = 0.0;
  window_start_ = t_s;
  if (!have_reference_) {  // the first window(s) up to reference_s are the reference
    f_ref_ = f;
    w_ref_ = w;
    have_reference_ = t_s - t_start_ >= cfg_.reference_s;
    return false;
  }
  const double dot = f[0] * f_ref_[0] + f[1] * f_ref_[1] + f[2] * f_ref_[2];
  const double tilt_deg = std::acos(std::clamp(dot / (norm(f) * norm(f_ref_)), -1.0, 1.0)) * kRadToDeg;
  const std::array<double, 3> dw{w[0] - w_ref_[0], w[1] - w_ref_[1], w[2] - w_ref_[2]};
  const double rate_deg_s = norm(dw) * kRadToDeg;
  if (tilt_deg > cfg_.tilt_limit_deg || rate_deg_s > cfg_.rate_limit_deg_s) {
    return mark(BenchEvent::Moved, start, t_s, std::max(tilt_deg, rate_deg_s));
  }
  return false;
}

bool BenchMonitor::close_temp_window(double t_s) {
  const double mean = temp_sum_ / temp_n_;
  const double start = temp_window_start_;
  temp_sum_ = temp_n_ = 0.0;
  temp_window_start_ = t_s;
  const bool step = have_prev_temp_ && std::abs(mean - prev_temp_) > cfg_.temp_step_degC;
  const double size = std::abs(mean - prev_temp_);
  prev_temp_ = mean;
  have_prev_temp_ = true;
  return step && mark(BenchEvent::TemperatureStep, start - cfg_.temp_window_s, t_s, size);
}

bool BenchMonitor::add(double t_s, const std::array<double, 3>& f, const std::array<double, 3>& w, double temp) {
  if (!started_) {
    started_ = true;
    t_start_ = window_start_ = temp_window_start_ = t_s;
  }
  bool fresh = false;
  if (t_s - window_start_ >= cfg_.window_s && n_ > 0.0) fresh |= close_motion_window(t_s);
  if (t_s - temp_window_start_ >= cfg_.temp_window_s && temp_n_ > 0.0) fresh |= close_temp_window(t_s);
  for (std::size_t i = 0; i < 3; ++i) {
    f_sum_[i] += f[i];
    w_sum_[i] += w[i];
  }
  n_ += 1.0;
  temp_sum_ += temp;
  temp_n_ += 1.0;
  return fresh;
}

}  // namespace sinu::calibration
