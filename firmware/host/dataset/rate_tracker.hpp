#pragma once
// Streams time stamps and reports count, span, nominal rate and gaps. A gap
// is an interval longer than the median of the first intervals (robust to a
// gap near the start) by half of it, or by three times their interquartile
// range where the stamps scatter more (an IMU stamped at receipt, +-4 ms at
// 100 Hz: intervals of 2-18 ms, read as 7,585 gaps and 107 Hz before session
// 37); the nominal rate is the mean over every interval that is not a gap (a
// median of jittered arrivals reads a 10-Hz receiver as 9.90 Hz).
#include <array>
#include <cstddef>

namespace sinu::dataset {

class RateTracker {
 public:
  void add(double t_s);
  void finish();  // call once after the last add()

  std::size_t count() const { return count_; }
  double first_s() const { return first_; }
  double last_s() const { return last_; }
  double duration_s() const { return count_ > 1 ? last_ - first_ : 0.0; }
  double nominal_period_s() const { return period_; }
  double nominal_rate_hz() const {
    return regular_ > 0 && regular_sum_s_ > 0.0 ? static_cast<double>(regular_) / regular_sum_s_
                                                : (period_ > 0.0 ? 1.0 / period_ : 0.0);
  }
  std::size_t gaps() const { return gaps_; }
  double longest_gap_s() const { return longest_; }
  double longest_gap_at_s() const { return longest_at_; }

 private:
  static constexpr std::size_t kWarmup = 101;  // intervals used for the median
  void classify(double dt, double t_end);

  std::array<double, kWarmup> warm_dt_{};
  std::array<double, kWarmup> warm_t_{};
  std::size_t warm_n_ = 0;
  std::size_t count_ = 0;
  double first_ = 0.0, last_ = 0.0, period_ = 0.0, gap_above_s_ = 0.0;
  std::size_t gaps_ = 0, regular_ = 0;
  double regular_sum_s_ = 0.0;
  double longest_ = 0.0, longest_at_ = 0.0;
};

}  // namespace sinu::dataset
