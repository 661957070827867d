#include "estimator/nav/vehicle_detector.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

void VehicleDetector::add(const NavState& nav, double dt_s, bool aided) {
  if (guess_ != VehicleGuess::Undecided) return;
  const Eigen::Matrix3d C_nb = nav.C_nb();
  const double yaw = std::atan2(C_nb(1, 0), C_nb(0, 0));
  const double speed = nav.v_n_m_s.head<2>().norm();
  const double course = std::atan2(nav.v_n_m_s.y(), nav.v_n_m_s.x());
  const bool moving = aided && speed >= cfg_.min_speed_m_s;
  double turn = 0.0, lateral_accel_g = 0.0;
  if (moving && have_yaw_ && dt_s > 0.0) {
    turn = std::abs(wrap_pi(yaw - last_yaw_rad_));
    // To the right, in g: the bank it would need.
    lateral_accel_g = speed * wrap_pi(course - last_course_rad_) / dt_s / wgs84::kStandardGravity;
  }
  last_yaw_rad_ = yaw;
  last_course_rad_ = course;
  have_yaw_ = moving;
  if (!moving) return;
  // Exponential memory over the time spent moving: the evidence is the last
  // `memory_s` of motion, so a start while the solution still converges is forgotten.
  const Eigen::Vector3d v_b = C_nb.transpose() * nav.v_n_m_s;
  const Eigen::Vector3d down_b = C_nb.row(2).transpose();
  const double keep = std::exp(-dt_s / cfg_.memory_s);
  moving_s_ += dt_s;
  weight_s_ = keep * weight_s_ + dt_s;
  turn_rad_ = keep * turn_rad_ + turn;
  vv_ = keep * vv_ + v_b * v_b.transpose() * dt_s;
  v_ = keep * v_ + v_b * dt_s;
  down_ = keep * down_ + down_b * dt_s;
  down_accel_ = keep * down_accel_ + down_b * (lateral_accel_g * dt_s);
  accel_ = keep * accel_ + lateral_accel_g * dt_s;
  accel2_ = keep * accel2_ + lateral_accel_g * lateral_accel_g * dt_s;
  if (moving_s_ < cfg_.min_moving_s || turn_rad_ < cfg_.min_turn_rad) return;
  if (rms_along(Eigen::Vector3d::UnitZ()) < cfg_.max_vertical_rms_m_s &&
      rms_along(Eigen::Vector3d::UnitY()) < cfg_.max_lateral_rms_m_s &&
      leans_out_of_turns(Eigen::Vector3d::UnitY())) {  // the contract's mounting
    guess_ = VehicleGuess::Ground;
    decided_at_s_ = nav.t_s;
    return;
  }
  VehicleAxes found;
  if (found_on_bracket(found)) {
    axes_ = found;
    on_bracket_ = true;
    guess_ = VehicleGuess::Ground;
    decided_at_s_ = nav.t_s;
  }
}

bool VehicleDetector::found_on_bracket(VehicleAxes& axes) const {
  // Forward: the principal axis of the body velocity (a constant heading
  // error turns it with the mount; the constraint then holds that heading).
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(vv_ / weight_s_);
  Eigen::Vector3d forward = eig.eigenvectors().col(2);
  if (forward.dot(v_) < 0.0) forward = -forward;
  // Vertical: the mean down, square to forward (roads are level on average).
  Eigen::Vector3d vertical = down_ - forward * forward.dot(down_);
  if (!(vertical.norm() > 1e-6 * weight_s_)) return false;
  vertical.normalize();
  const Eigen::Vector3d lateral = vertical.cross(forward);
  // Across the motion within mounted_lateral_rms_m_s: looser than the
  // contract's. Without a magnetometer and the constraint a car's heading
  // wanders by degrees (the real drive turned 90 deg: 0.6-1.4 m/s across in
  // its first 3 minutes; 0.13 along body y as mounted; turned 45 deg and cut
  // to start driving, 1.0-1.5 m/s for three minutes: at 1.0 m/s found 165 s
  // after the start, 7.4 m over the seven outages after it, at 1.5 m/s 113 s
  // and 5.9 m). A constant heading error turns the axis and adds nothing
  // across (the vehicle_mount state takes it). The vertical limit and the
  // bank tell an aircraft.
  if (rms_along(lateral) >= cfg_.mounted_lateral_rms_m_s || rms_along(vertical) >= cfg_.max_vertical_rms_m_s ||
      !leans_out_of_turns(lateral))
    return false;
  // Level on the vehicle, as a bracket mostly is: the tilt found is the
  // solution's tilt error of the moment (about 1 deg on the real drive) as
  // much as the bracket's. A pitch or roll within `square_tilt_rad` of a
  // quarter turn is taken as that quarter turn. (The yaw found carries the
  // heading's error; the vehicle_mount state takes that over.)
  const Eigen::Vector3d euler = VehicleAxes{lateral, vertical}.unit_euler_rad();
  const auto squared = [](double angle_rad, double within_rad) {
    const double quarter = std::numbers::pi / 2.0, square = quarter * std::round(angle_rad / quarter);
    return std::abs(angle_rad - square) < within_rad ? square : angle_rad;
  };
  const Eigen::Matrix3d C_vb = (Eigen::AngleAxisd(euler.z(), Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(squared(euler.y(), cfg_.square_tilt_rad), Eigen::Vector3d::UnitY()) *
                                Eigen::AngleAxisd(squared(euler.x(), cfg_.square_tilt_rad), Eigen::Vector3d::UnitX()))
                                   .toRotationMatrix();
  axes.lateral_b = C_vb.row(1).transpose();
  axes.vertical_b = C_vb.row(2).transpose();
  return true;
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

double VehicleDetector::bank_per_g_along(const Eigen::Vector3d& lateral) const {
  const double mean_accel = weight_s_ > 0.0 ? accel_ / weight_s_ : 0.0;
  const double accel_var = weight_s_ > 0.0 ? accel2_ / weight_s_ - mean_accel * mean_accel : 0.0;
  if (!(accel_var >= cfg_.min_lateral_accel_spread_g * cfg_.min_lateral_accel_spread_g))
    return std::numeric_limits<double>::quiet_NaN();
  // The bank (down along the lateral axis: sin of the roll) regressed on the lateral acceleration.
  return (lateral.dot(down_accel_) / weight_s_ - lateral.dot(down_) / weight_s_ * mean_accel) / accel_var;
}

bool VehicleDetector::leans_out_of_turns(const Eigen::Vector3d& lateral) const {
  return bank_per_g_along(lateral) < cfg_.max_bank_per_g;  // false while NaN: no evidence
}

double VehicleDetector::rms_along(const Eigen::Vector3d& a) const {
  return weight_s_ > 0.0 ? std::sqrt(std::max(0.0, a.dot(vv_ * a)) / weight_s_) : 0.0;
}

}  // namespace sinu::est
