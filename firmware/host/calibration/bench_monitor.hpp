#pragma once
// Watches a bench session while it is recorded: the noise models assume the
// board stands still at one temperature, so a move (the specific force's
// direction or the mean rate changing) or a temperature step is warned about
// at once and marked, with its time span, in the session's bench.json.
#include <array>
#include <vector>

namespace sinu::calibration {

enum class BenchEvent { Moved, TemperatureStep };

struct BenchMark {
  BenchEvent event = BenchEvent::Moved;
  double start_s = 0.0, end_s = 0.0;
  double size = 0.0;  // largest tilt [deg] or rate change [deg/s] (Moved), or step [degC]
};

struct BenchMonitorConfig {
  double reference_s = 10.0;       // the still attitude and rate: the first seconds' means
  double window_s = 1.0;           // motion is judged on 1-s means
  // 1-s means of a MEMS IMU's noise are ~0.005 deg of tilt and ~0.01 deg/s;
  // its accelerometer bias drifts ~1 mg/degC (0.06 deg) and a simulated
  // session's bias processes wander ~0.2 deg in minutes: these limits see a
  // nudge of the bench, not the noise or the drift.
  double tilt_limit_deg = 0.5;
  double rate_limit_deg_s = 0.3;
  double temp_window_s = 10.0;     // temperature on 10-s means
  double temp_step_degC = 0.5;     // between consecutive means (a warm-up drifts ~0.1 degC per 10 s)
};

class BenchMonitor {
 public:
  explicit BenchMonitor(const BenchMonitorConfig& config = {});
  /// One sample; true when it starts a new mark (warn the user).
  bool add(double t_s, const std::array<double, 3>& specific_force, const std::array<double, 3>& rate_rad_s,
           double temp_degC);
  const std::vector<BenchMark>& marks() const { return marks_; }

 private:
  bool close_motion_window(double t_s);
  bool close_temp_window(double t_s);
  bool mark(BenchEvent e, double start_s, double end_s, double size);

  BenchMonitorConfig cfg_;
  bool have_reference_ = false, started_ = false;
  double t_start_ = 0.0;
  std::array<double, 3> f_ref_{}, w_ref_{}, f_sum_{}, w_sum_{};
  double n_ = 0.0, window_start_ = 0.0;
  double temp_sum_ = 0.0, temp_n_ = 0.0, temp_window_start_ = 0.0, prev_temp_ = 0.0;
  bool have_prev_temp_ = false;
  std::vector<BenchMark> marks_;
};

const char* bench_event_name(BenchEvent e);  // "moved", "temperature_step"

}  // namespace sinu::calibration
