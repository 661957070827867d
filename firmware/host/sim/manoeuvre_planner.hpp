#pragma once
// Seeded random sequence of flight manoeuvres. A fixed wing: a minute still
// on the ground, take-off roll, climb-out, then straight legs, coordinated
// turns (bank 15-35 deg), loiter circles, figure-eights, climbs and descents
// (100-300 m above ground), speed changes (33-47 m/s around the paper's 40
// m/s = 145 km/h), and a final descent. A multirotor
// (manoeuvre_planner_multirotor.cpp): a minute on the ground, a vertical
// climb to 30-60 m, then survey legs, turns, hover stops, climbs and descents
// (20-80 m above ground), and a vertical landing (airframe.hpp). Each
// manoeuvre is a few primitives; a primitive ramps the controls to new
// targets and holds them.
#include <array>
#include <cstddef>

#include "firmware/host/sim/airframe.hpp"
#include "firmware/host/sim/flight_controls.hpp"
#include "firmware/host/sim/rng.hpp"

namespace sinu::sim {

struct Primitive {
  double ramp_s = 1.0;   // cosine ramp of every control to its target
  double hold_s = 0.0;   // then hold
  double speed_m_s = 0.0, gamma_rad = 0.0, bank_rad = 0.0, alpha_rad = 0.0;
  const char* name = "";
};

/// What the planner needs to know when it chooses the next manoeuvre.
struct PlannerInput {
  double t_s = 0.0;          // now
  double end_s = 0.0;        // end of the flight
  double height_agl_m = 0.0;  // above the ground at the take-off point
};

class ManoeuvrePlanner {
 public:
  ManoeuvrePlanner(Rng& rng, Airframe airframe) : rng_(rng), airframe_(airframe) {}
  /// The next primitive to fly, given the current state.
  Primitive next(const PlannerInput& in);

 private:
  void plan(const PlannerInput& in);
  void plan_multirotor(const PlannerInput& in);
  void push(const Primitive& p);
  /// A coordinated turn through turn_rad at the current speed, then the roll-out; alpha held.
  void plan_turn(double bank_rad, double turn_rad, double ramp_s, double alpha_rad);
  /// A multirotor's primitive: the body level but for its tilt into the horizontal speed, whatever the flight path.
  Primitive multirotor(double ramp_s, double hold_s, double speed_m_s, double gamma_rad, double bank_rad,
                       const char* name) const;
  void plan_height_change(double dh_m);
  double final_descent_s(double agl_m) const;

  enum class Phase { Ground, TakeoffRoll, Climbout, Cruise, FinalDescent, Done };
  Rng& rng_;
  Airframe airframe_;
  Phase phase_ = Phase::Ground;
  double speed_m_s_ = 0.0;  // speed target of the last primitive queued
  std::array<Primitive, 8> queue_{};
  std::size_t head_ = 0, size_ = 0;
};

}  // namespace sinu::sim
