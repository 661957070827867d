#include "firmware/host/dataset/rate_tracker.hpp"

#include <algorithm>

namespace sinu::dataset {

namespace {
constexpr double kGapMargin = 0.5;  // of the nominal period: beyond it, a gap
constexpr double kGapSpread = 3.0;  // interquartile ranges: beyond them, a gap
}

void RateTracker::classify(double dt, double t_end) {
  if (dt <= gap_above_s_) {
    ++regular_;
    regular_sum_s_ += dt;
  } else {
    ++gaps_;
    if (dt > longest_) {
      longest_ = dt;
      longest_at_ = t_end - dt;
    }
  }
}

void RateTracker::add(double t) {
  if (count_++ == 0) {
    first_ = last_ = t;
    return;
  }
  const double dt = t - last_;
  last_ = t;
  if (period_ > 0.0) {
    classify(dt, t);
    return;
  }
  warm_dt_[warm_n_] = dt;
  warm_t_[warm_n_] = t;
  if (++warm_n_ == kWarmup) finish();
}

void RateTracker::finish() {
  if (period_ > 0.0 || warm_n_ == 0) return;
  std::array<double, kWarmup> sorted = warm_dt_;
  std::sort(sorted.begin(), sorted.begin() + static_cast<long>(warm_n_));
  period_ = sorted[warm_n_ / 2];
  const double iqr = sorted[3 * warm_n_ / 4] - sorted[warm_n_ / 4];
  gap_above_s_ = period_ + std::max(kGapMargin * period_, kGapSpread * iqr);
  for (std::size_t i = 0; i < warm_n_; ++i) classify(warm_dt_[i], warm_t_[i]);
}

}  // namespace sinu::dataset
