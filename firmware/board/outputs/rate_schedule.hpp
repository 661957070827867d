#pragma once
// When a periodic output is due, on the time line of the solutions that drive
// it. The first solution is due; then one every period, the due times
// advancing by whole periods (so the mean rate is exact whatever the solution
// rate), re-anchored on the current time after a gap longer than a period.
namespace sinu::board {

class RateSchedule {
 public:
  /// `rate_hz` <= 0: never due.
  explicit RateSchedule(double rate_hz) : period_s_(rate_hz > 0.0 ? 1.0 / rate_hz : 0.0) {}

  /// True if the output is due at `t_s` (call once per solution, in time order).
  bool due(double t_s) {
    if (period_s_ <= 0.0) return false;
    if (started_ && t_s < next_s_ - kSlackS) return false;
    next_s_ = started_ ? next_s_ + period_s_ : t_s + period_s_;
    if (next_s_ <= t_s) next_s_ = t_s + period_s_;  // a gap: do not send a burst to catch up
    started_ = true;
    return true;
  }

  double period_s() const { return period_s_; }

 private:
  static constexpr double kSlackS = 1e-6;  // solution times are sums of sample intervals: rounding
  double period_s_;
  double next_s_ = 0.0;
  bool started_ = false;
};

}  // namespace sinu::board
