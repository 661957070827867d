#include "firmware/host/dataset/imu_row_merger.hpp"

#include <algorithm>

namespace sinu::dataset {

namespace {
Eigen::Vector3d vec(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }
}  // namespace

void ImuRowMerger::push_ready(const est::ImuSample& s) {
  ready_[(ready_head_ + n_ready_) % ready_.size()] = s;
  ++n_ready_;
}

bool ImuRowMerger::next(est::ImuSample& out) {
  if (n_ready_ == 0) return false;
  out = ready_[ready_head_];
  ready_head_ = (ready_head_ + 1) % ready_.size();
  --n_ready_;
  return true;
}

// The waiting gyro rows, in order: interpolated between last_accel_ and
// `after` (the reading that ends their wait), or last_accel_ held (none).
void ImuRowMerger::release_waiting(const Accel* after) {
  const double span = after ? after->t_s - last_accel_.t_s : 0.0;
  for (std::size_t k = 0; k < n_waiting_; ++k) {
    est::ImuSample s = waiting_[k];
    if (after && span > 0.0) {
      // Clamped: stamps out of order (dropped and counted downstream) must not extrapolate.
      const double w = std::clamp((s.t_s - last_accel_.t_s) / span, 0.0, 1.0);
      s.specific_force_b_m_s2 = last_accel_.f + w * (after->f - last_accel_.f);
      ++counts_.accel_interpolated;
    } else {
      s.specific_force_b_m_s2 = last_accel_.f;
      ++counts_.accel_held;
    }
    push_ready(s);
  }
  n_waiting_ = 0;
}

void ImuRowMerger::add(const ImuRow& r) {
  if (r.has_mag()) {
    pending_.mag_b_uT = vec(r.mag_b_uT());
    pending_.has_mag = true;
  }
  if (r.has_temp()) {
    pending_.temp_degC = r.temp_degC();
    pending_.has_temp = true;
  }
  if (r.has_accel()) {
    const Accel a{r.t_s(), vec(r.specific_force_b_m_s2())};
    if (n_waiting_ > 0) release_waiting(&a);
    last_accel_ = a;
    have_accel_ = true;
  }
  if (!r.has_gyro()) {
    ++counts_.rows_folded;
    return;
  }
  est::ImuSample s = pending_;
  pending_ = est::ImuSample{};
  s.t_s = r.t_s();
  s.angular_rate_b_rad_s = vec(r.angular_rate_b_rad_s());
  if (r.has_accel()) {
    s.specific_force_b_m_s2 = last_accel_.f;  // this row's, just taken
    push_ready(s);
    return;
  }
  if (!have_accel_) {
    ++counts_.left_out;
    return;
  }
  if (n_waiting_ == waiting_.size()) release_waiting(nullptr);  // the accelerometer fell silent: hold
  waiting_[n_waiting_++] = s;
}

void ImuRowMerger::finish() {
  if (n_waiting_ > 0) release_waiting(nullptr);
}

}  // namespace sinu::dataset
