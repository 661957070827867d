#include "firmware/host/dataset/rate_tracker.hpp"

#include <algorithm>

namespace sinu::dataset {

namespace {
constexpr double kGapFactor = 1.5;  // an interval this many nominal periods long is a gap
}

void RateTracker::classify(double dt, double t_end) {
  if (dt <= kGapFactor * period_) {
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
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(warm_n_ / 2),
                   sorted.begin() + static_cast<long>(warm_n_));
  period_ = sorted[warm_n_ / 2];
  for (std::size_t i = 0; i < warm_n_; ++i) classify(warm_dt_[i], warm_t_[i]);
}

}  // namespace sinu::dataset
