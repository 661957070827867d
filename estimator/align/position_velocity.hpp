#pragma once
// A receiver that sends positions only (GGA or GLL, no RMC or VTG) gives the
// alignment no velocity, and without a magnetometer no heading: the unit
// never aligned. Its velocity over the last baseline_s of fixes stands in,
// for the alignment only: a backward difference, so it is late by half the
// baseline (lag_accel_m_s2 * baseline / 2 in the sigma), and its noise is
// the fixes' short-term (white) part, sqrt(2 white_fraction) sigma_h / T:
// a receiver's position error is mostly slow (the filter's GPS bias model),
// and consecutive fixes share it. Good enough for the course at take-off and
// for telling rest from motion; the in-motion alignment, whose fit takes the
// velocity at the fix's own time, does not use it.
#include <array>
#include <cstddef>

#include "estimator/ekf/aiding/gnss_observation.hpp"

namespace sinu::est {

struct PositionVelocityConfig {
  double baseline_s = 1.0;       // difference over at least this
  double max_baseline_s = 3.0;   // a gap longer than this: no velocity
  double white_fraction = 0.1;   // of the fix's stated variance (the rest is slow, shared by both fixes)
  double lag_accel_m_s2 = 1.0;   // acceleration the lag is allowed for (a car pulling away, a take-off run)
};

class PositionVelocity {
 public:
  void configure(const PositionVelocityConfig& cfg) {
    cfg_ = cfg;
    reset();
  }
  void reset() { count_ = 0; }
  /// When z has a position but no velocity: its velocity from the fixes
  /// before it (has_velocity, velocity_from_positions set; false while there
  /// is no fix baseline_s..max_baseline_s earlier). Remembers z's position.
  bool fill(GnssObservation& z);

 private:
  struct Fix {
    double t_s = 0.0, lat_rad = 0.0, lon_rad = 0.0, sigma_h_m = 0.0;
  };
  static constexpr std::size_t kFixes = 32;  // 3 s at 10 Hz
  PositionVelocityConfig cfg_;
  std::array<Fix, kFixes> fixes_{};
  std::size_t next_ = 0, count_ = 0;
};

}  // namespace sinu::est
