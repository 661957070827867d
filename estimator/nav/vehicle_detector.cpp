#include "estimator/nav/vehicle_detector.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sinu::est {

void VehicleDetector::add(const NavState& nav, double dt_s, bool aided) {
  if (guess_ != VehicleGuess::Undecided) return;
  const Eigen::Matrix3d C_nb = nav.C_nb();
  const double yaw = std::atan2(C_nb(1, 0), C_nb(0, 0));
  const bool moving = aided && nav.v_n_m_s.head<2>().norm() >= cfg_.min_speed_m_s;
  double turn = 0.0;
  if (moving && have_yaw_) {
    turn = yaw - last_yaw_rad_;
    turn = std::abs(turn - 2.0 * std::numbers::pi * std::round(turn / (2.0 * std::numbers::pi)));
  }
  last_yaw_rad_ = yaw;
  have_yaw_ = moving;
  if (!moving) return;
  // Exponential memory over the time spent moving: the evidence is the last
  // `memory_s` of motion, so a start while the solution still converges is forgotten.
  const Eigen::Vector3d v_b = C_nb.transpose() * nav.v_n_m_s;
  const double keep = std::exp(-dt_s / cfg_.memory_s);
  moving_s_ += dt_s;
  weight_s_ = keep * weight_s_ + dt_s;
  turn_rad_ = keep * turn_rad_ + turn;
  sum_lat2_ = keep * sum_lat2_ + v_b.y() * v_b.y() * dt_s;
  sum_fwd2_ = keep * sum_fwd2_ + v_b.x() * v_b.x() * dt_s;
  sum_cross_ = keep * sum_cross_ + v_b.x() * v_b.y() * dt_s;
  sum_vert2_ = keep * sum_vert2_ + v_b.z() * v_b.z() * dt_s;
  if (moving_s_ < cfg_.min_moving_s || turn_rad_ < cfg_.min_turn_rad) return;
  if (vertical_rms_m_s() >= cfg_.max_vertical_rms_m_s) return;
  if (lateral_rms_about(1) < cfg_.max_lateral_rms_m_s) {  // the contract's mounting
    guess_ = VehicleGuess::Ground;
    decided_at_s_ = nav.t_s;
    return;
  }
  // Mounted sideways: the motion along body y, and across it (about the
  // principal axis of the horizontal body velocity, which a constant heading
  // error turns) within sideways_lateral_rms_m_s. Looser: such a unit
  // without a magnetometer had its heading from the course check, known to
  // 5-20 deg, and without the constraint a car's heading wanders by degrees
  // (the real drive turned 90 deg: 0.6-1.4 m/s across in its first 3
  // minutes; 0.13 along body y as mounted). The vertical limit is what tells
  // an aircraft (1.7-1.8 m/s), and the constraint, once on, holds the heading.
  if (sum_lat2_ > sum_fwd2_ && lateral_rms_about(0) < cfg_.sideways_lateral_rms_m_s) {
    lateral_axis_ = 0;
    guess_ = VehicleGuess::Ground;
    decided_at_s_ = nav.t_s;
  }
}

void VehicleDetector::on_constraint(double t_s, bool accepted) {
  if (guess_ != VehicleGuess::Ground) return;
  if (nhc_tried_ == 0) window_start_s_ = t_s;  // a window starts with its first update
  ++nhc_tried_;
  if (!accepted) ++nhc_rejected_;
  if (t_s - window_start_s_ < cfg_.revert_window_s) return;
  if (2 * nhc_rejected_ > nhc_tried_) guess_ = VehicleGuess::Reverted;  // the constraint does not hold
  nhc_tried_ = nhc_rejected_ = 0;
  window_start_s_ = t_s;
}

double VehicleDetector::lateral_rms_about(int axis) const {
  if (!(weight_s_ > 0.0)) return 0.0;
  if (axis == 1) return std::sqrt(sum_lat2_ / weight_s_);
  // Sideways: across the principal axis of the horizontal body velocity (its smaller eigenvalue).
  const double spread = std::hypot(sum_fwd2_ - sum_lat2_, 2.0 * sum_cross_);
  return std::sqrt(std::max(0.0, 0.5 * (sum_fwd2_ + sum_lat2_ - spread)) / weight_s_);
}
double VehicleDetector::vertical_rms_m_s() const { return weight_s_ > 0.0 ? std::sqrt(sum_vert2_ / weight_s_) : 0.0; }

}  // namespace sinu::est
