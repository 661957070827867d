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
// below their limits; until then it is treated as an aircraft (no
// constraint: the safe side). Then the navigator adds the non-holonomic
// constraint and zero-velocity updates at stops; if the constraint is then
// rejected more often than not over `revert_window_s` (the guess was wrong:
// an aircraft's take-off run, then flight), it goes back to air for good.
//
// A unit mounted sideways (its x axis across the vehicle: the contract says
// x forward, a bracket may not) moves along its body x hardly at all: its
// body x is then the lateral axis, and the constraint is applied so
// (lateral_axis). Only the two body axes: a unit at 45 deg on its mount
// stays undetected (an aircraft to the filter, no constraint).
//
// Measured (the solution without the constraint): the real car drive_0708,
// body z 0.05-0.10 m/s RMS per minute, lateral 0.07-0.43 (heading not yet
// held by the constraint); the simulator's UAV 1.8 / 0.5 m/s; the real
// quadcopter uav_log171 1.7 / 2.1 m/s.
#include <cstdint>

#include "estimator/ins/nav_state.hpp"

namespace sinu::est {

struct VehicleDetectorConfig {
  double min_speed_m_s = 3.0;         // slower motion says little (a body-z error is speed x tilt error)
  double min_moving_s = 30.0;
  double memory_s = 60.0;              // of motion: the evidence's exponential memory
  double min_turn_rad = 1.57;          // heading changes summed (with the same memory) while moving
  double max_vertical_rms_m_s = 0.25;  // body z
  double max_lateral_rms_m_s = 0.5;    // body y: looser, the heading is the least known angle
  double sideways_lateral_rms_m_s = 1.0;  // a unit mounted sideways, about its motion's axis (vehicle_detector.cpp)
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
    moving_s_ = weight_s_ = turn_rad_ = sum_lat2_ = sum_fwd2_ = sum_vert2_ = sum_cross_ = decided_at_s_ = 0.0;
    lateral_axis_ = 1;
    have_yaw_ = false;
    nhc_tried_ = nhc_rejected_ = 0;
    window_start_s_ = 0.0;
  }
  /// One processed sample: the solution (aided by GNSS within the last
  /// second: `aided`) and its interval.
  void add(const NavState& nav, double dt_s, bool aided);
  /// The outcome of a non-holonomic update while the guess is Ground.
  void on_constraint(double t_s, bool accepted);

  VehicleGuess guess() const { return guess_; }
  /// The body axis across the vehicle: 1 (y, the contract's x forward) or 0 (x: mounted sideways).
  int lateral_axis() const { return lateral_axis_; }
  double decided_at_s() const { return decided_at_s_; }
  /// The evidence so far (or at the decision): body-frame RMS over the memory [m/s] (lateral: along
  /// lateral_axis()), time moving [s].
  double lateral_rms_m_s() const { return lateral_rms_about(lateral_axis_); }
  double vertical_rms_m_s() const;
  double moving_s() const { return moving_s_; }

 private:
  /// Across body y (axis 1), or, for axis 0, across the principal axis of the horizontal body velocity.
  double lateral_rms_about(int axis) const;
  VehicleDetectorConfig cfg_;
  VehicleGuess guess_ = VehicleGuess::Undecided;
  double moving_s_ = 0.0, weight_s_ = 0.0, turn_rad_ = 0.0, sum_lat2_ = 0.0, sum_fwd2_ = 0.0, sum_vert2_ = 0.0;
  double sum_cross_ = 0.0;  // body x times y
  int lateral_axis_ = 1;
  double last_yaw_rad_ = 0.0, decided_at_s_ = 0.0, window_start_s_ = 0.0;
  bool have_yaw_ = false;
  int nhc_tried_ = 0, nhc_rejected_ = 0;
};

}  // namespace sinu::est
