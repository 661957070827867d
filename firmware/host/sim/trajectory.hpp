#pragma once
// The flight trajectory, integrated on WGS-84 on a fixed internal grid
// (substep_s, several hundred Hz): heading from the coordinated-turn rate,
// latitude/longitude/height from the NED velocity (midpoint rule). Controls
// come from the ManoeuvrePlanner. The motion at any instant between two grid
// points is a partial step from the last one, so events off the grid (GPS
// fixes with latency) never change the grid trajectory itself.
#include <cstdint>

#include "firmware/host/sim/flight_controls.hpp"
#include "firmware/host/sim/manoeuvre_planner.hpp"
#include "firmware/host/sim/true_motion.hpp"

namespace sinu::sim {

struct Site {
  double lat_rad = 0.0, lon_rad = 0.0;
  double ground_h_m = 0.0;  // ellipsoidal height of the runway
  double heading_rad = 0.0; // initial heading (runway direction)
};

/// A random plausible site: |lat| < 60 deg, ground 0-600 m.
Site draw_site(Rng& rng);

class Trajectory {
 public:
  Trajectory(const Site& site, double t0_s, double end_s, double substep_s, Rng& rng,
             Airframe airframe = Airframe::FixedWing);
  /// Motion at the current grid point.
  TrueMotion motion() const;
  /// Motion at t in [time(), time() + substep], without advancing.
  TrueMotion motion_at(double t_s) const;
  /// Advances one substep.
  void step();
  double time() const { return t0_s_ + static_cast<double>(index_) * substep_s_; }
  std::uint64_t index() const { return index_; }
  const char* manoeuvre() const { return primitive_.name; }

 private:
  void begin_primitive_if_due();
  NavState derivative(double t_s, const NavState& s) const;
  NavState advanced(const NavState& s, double t_s, double dt_s) const;

  Site site_;
  double t0_s_, end_s_, substep_s_;
  std::uint64_t index_ = 0;
  ManoeuvrePlanner planner_;
  FlightControls controls_;
  Primitive primitive_{};
  double primitive_end_s_ = 0.0;
  NavState state_;
};

}  // namespace sinu::sim
