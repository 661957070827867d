#pragma once
// A receiver that holds its course at low speed: u-blox (gpsd's ublox-8 and
// ublox-zed-f9p logs, the real quadcopter uav_log171: 175 of its 578 epochs
// under 1.5 m/s), Unicore, MTK repeat the last course to the digit while the
// speed they report changes. Speed times that course is no velocity: in a
// hover spin the independent simulator's receiver held 262.58 deg with
// 0.1-0.26 m/s of lever-arm speed, and fused as a vector it dragged the
// solution 2.2 m west in 20 s (2.63 m horizontal RMSE over the flight, the
// fixes alone 1.31 m). An epoch whose direction of velocity repeats the
// previous `repeats` epochs' exactly while the speed moves, below
// `max_speed_m_s`, has its course held: its speed is a measurement, its
// direction is not, and the navigator fuses it as a velocity of zero within
// that speed. (A course really measured at 1.5 m/s scatters by degrees:
// three equal to a receiver's last digit in a row do not happen.)
#include <cmath>
#include <Eigen/Core>

namespace sinu::est {

struct CourseHoldConfig {
  double max_speed_m_s = 1.5;
  int repeats = 2;
};

class CourseHold {
 public:
  void configure(const CourseHoldConfig& cfg) {
    cfg_ = cfg;
    run_ = 0;
    have_last_ = false;
  }
  /// One epoch's horizontal velocity [m/s], in arrival order: true when its course is held.
  bool held(const Eigen::Vector2d& v_ne_m_s) {
    const double speed = v_ne_m_s.norm(), course = std::atan2(v_ne_m_s.y(), v_ne_m_s.x());
    const bool same = have_last_ && speed > 0.0 && last_speed_ > 0.0 && std::abs(course - last_course_) < 1e-9 &&
                      std::abs(speed - last_speed_) > 1e-9;
    run_ = speed < cfg_.max_speed_m_s && same ? run_ + 1 : 0;
    have_last_ = true;
    last_speed_ = speed;
    last_course_ = course;
    return run_ >= cfg_.repeats;
  }

 private:
  CourseHoldConfig cfg_;
  int run_ = 0;
  bool have_last_ = false;
  double last_speed_ = 0.0, last_course_ = 0.0;
};

}  // namespace sinu::est
