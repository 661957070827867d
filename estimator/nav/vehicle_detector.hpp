#pragma once
// What carries the unit, when nobody said (`vehicle = auto`, the default):
// a ground vehicle's wheels neither slide sideways nor leave the road, so its
// velocity in the body frame has no lateral and no vertical component; an
// aircraft's has both (angle of attack: a fixed wing at 40 m/s and 2 deg
// flies 1.4 m/s along body z; a multirotor pitches into its motion and slides
// sideways; a crosswind crabs both). The detector watches the solution's own
// body-frame velocity while moving and GNSS-aided, and declares a ground
// vehicle once, after at least `min_moving_s` of motion, the last
// `memory_s` of it (turns of `min_turn_rad` among them) show both components
// below their limits and no bank into the turns (below); until then it is
// treated as an aircraft (no constraint: the safe side). Then the navigator
// adds the non-holonomic constraint and zero-velocity updates at stops; if
// the constraint is then rejected more often than not over
// `revert_window_s` (the guess was wrong: an aircraft's take-off run, then
// flight), it goes back to air for good.
//
// The velocity alone does not tell every aircraft: a multirotor surveying
// at 4 m/s nose first, pitched 3 deg, has 0.2 m/s along body z and nothing
// sideways, below both limits. The turn does: an aircraft banks into it, by
// atan(a / g) of its lateral acceleration a, a car does not (it leans out, a
// few degrees per g). The slope of the body's bank on a / g over the memory:
// the real car -0.03..-0.16, the simulator's fixed wings 0.84-0.95, the real
// quadcopter 0.71-0.79; a ground vehicle must show less than
// `max_bank_per_g`. A steady circle is no evidence either way (every bank is
// then a mount), so the lateral acceleration must vary by
// `min_lateral_accel_spread_g`.
//
// A unit on a bracket (turned on it, tilted: the contract says x forward, a
// bracket may not) moves along a body direction that is not x. Its body
// velocity then lies along the principal axis of its second moment, the
// vehicle's forward axis; its vertical axis is the mean down in the body
// frame made square to it; the constraint acts along the lateral and vertical
// axes so found (axes()). An aircraft at a steady angle of attack reads the
// same way (the simulator's fixed wing like a car with its unit pitched 3
// deg): the bank tells it here too.
//
// Measured (the solution without the constraint): the real car drive_0708,
// body z 0.05-0.10 m/s RMS per minute, lateral 0.07-0.43 (heading not yet
// held by the constraint); the simulator's UAV 1.8 / 0.5 m/s; the real
// quadcopter uav_log171 1.7 / 2.1 m/s.
#include <cstdint>

#include "estimator/ekf/aiding/nonholonomic/nonholonomic.hpp"
#include "estimator/ins/nav_state.hpp"

namespace sinu::est {

struct VehicleDetectorConfig {
  double min_speed_m_s = 3.0;         // slower motion says little (a body-z error is speed x tilt error)
  // 20 s and 1 rad (57 deg) of turning: the real drive cut 100 s in, driving, found at 30 s and 90 deg only 58 s
  // after its alignment, after its first outage (21.3 m, with the constraint 2.7 m); the aircraft's evidence is
  // its body-z velocity (1.6-2.1 m/s) and its bank into the turns (session 35-36, docs/experiments.md).
  double min_moving_s = 20.0;
  double memory_s = 60.0;              // of motion: the evidence's exponential memory
  double min_turn_rad = 1.0;           // heading changes summed (with the same memory) while moving
  double max_vertical_rms_m_s = 0.25;  // body z
  double max_lateral_rms_m_s = 0.5;    // body y: looser, the heading is the least known angle
  double mounted_lateral_rms_m_s = 1.5;  // a unit on a bracket: across its motion's axis (vehicle_detector.cpp)
  double max_bank_per_g = 0.4;           // a ground vehicle's body banks less than this into a turn
  double min_lateral_accel_spread_g = 0.03;  // ... judged only where the turns vary (the real car: 0.08 g RMS)
  double square_tilt_rad = 0.052;  // a bracket's pitch and roll found within 3 deg of a quarter turn are that turn
  double revert_window_s = 10.0;
};

/// Undecided: an aircraft until shown otherwise. Reverted: was Ground, the constraint failed.
enum class VehicleGuess : std::uint8_t { Undecided, Ground, Reverted };

class VehicleDetector {
 public:
  void configure(const VehicleDetectorConfig& cfg) {
    cfg_ = cfg;
    restart();
  }
  /// Forgets the evidence: the solution it came from was wrong (a heading turned by the course check).
  void restart() {
    guess_ = VehicleGuess::Undecided;
    moving_s_ = weight_s_ = turn_rad_ = decided_at_s_ = 0.0;
    vv_.setZero();
    v_.setZero();
    down_.setZero();
    down_accel_.setZero();
    accel_ = accel2_ = 0.0;
    axes_ = VehicleAxes{};
    on_bracket_ = false;
    have_yaw_ = false;
    nhc_tried_ = nhc_rejected_ = 0;
    window_start_s_ = 0.0;
    restored_ = false;
  }
  /// A restart's: the ground vehicle and its axes found before it (the state file). The same vehicle carries
  /// the unit; a constraint that then fails still reverts it.
  void restore(const VehicleAxes& axes, bool on_bracket) {
    restart();
    guess_ = VehicleGuess::Ground;
    axes_ = axes;
    on_bracket_ = on_bracket;
    restored_ = true;
  }
  /// One processed sample: the solution (aided by GNSS within the last
  /// second: `aided`) and its interval.
  void add(const NavState& nav, double dt_s, bool aided);
  /// The outcome of a non-holonomic update while the guess is Ground.
  void on_constraint(double t_s, bool accepted);

  VehicleGuess guess() const { return guess_; }
  /// The vehicle's lateral and vertical axes in the body frame: y and z as the contract mounts the unit, or as
  /// found for a unit on a bracket (on_bracket()).
  const VehicleAxes& axes() const { return axes_; }
  bool on_bracket() const { return on_bracket_; }
  double decided_at_s() const { return decided_at_s_; }
  /// The guess came from before a restart (restore), not from this run's motion.
  bool restored() const { return restored_; }
  /// The evidence so far (or at the decision): the body velocity's RMS along axes() over the memory [m/s], time
  /// moving [s].
  double lateral_rms_m_s() const { return rms_along(axes_.lateral_b); }
  double vertical_rms_m_s() const { return rms_along(axes_.vertical_b); }
  /// The body's bank into the turns per g of lateral acceleration (NaN while the turns vary too little to tell).
  double bank_per_g() const { return bank_per_g_along(axes_.lateral_b); }
  double moving_s() const { return moving_s_; }

 private:
  double rms_along(const Eigen::Vector3d& a) const;
  /// The axes of a unit on a bracket from the evidence; true when they hold the velocity and the body does not
  /// bank into the turns.
  bool found_on_bracket(VehicleAxes& axes) const;
  /// The body, rolled about `lateral`, banks less than max_bank_per_g into turns that vary enough to tell.
  bool leans_out_of_turns(const Eigen::Vector3d& lateral) const;
  double bank_per_g_along(const Eigen::Vector3d& lateral) const;
  VehicleDetectorConfig cfg_;
  VehicleGuess guess_ = VehicleGuess::Undecided;
  // Exponentially weighted sums over the time moving (weight_s_ is the sum of the weights):
  Eigen::Matrix3d vv_ = Eigen::Matrix3d::Zero();  // body velocity's second moment [m^2/s^2 s]
  Eigen::Vector3d v_ = Eigen::Vector3d::Zero();   // body velocity [m/s s]
  Eigen::Vector3d down_ = Eigen::Vector3d::Zero();  // the navigation frame's down in the body frame [s]
  Eigen::Vector3d down_accel_ = Eigen::Vector3d::Zero();  // that times the lateral acceleration [g s]
  double accel_ = 0.0, accel2_ = 0.0;  // lateral acceleration (speed times course rate) [g s], [g^2 s]
  double moving_s_ = 0.0, weight_s_ = 0.0, turn_rad_ = 0.0;
  VehicleAxes axes_;
  bool on_bracket_ = false;
  double last_yaw_rad_ = 0.0, last_course_rad_ = 0.0, decided_at_s_ = 0.0, window_start_s_ = 0.0;
  bool have_yaw_ = false, restored_ = false;
  int nhc_tried_ = 0, nhc_rejected_ = 0;
};

}  // namespace sinu::est
