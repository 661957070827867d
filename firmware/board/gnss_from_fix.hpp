#pragma once
// drivers::GpsFix (one NMEA epoch) -> est::GnssObservation. Position sigma
// stated by the receiver: from GST when present, else by an RTK fix quality
// (fixed / float); otherwise a guess the navigator rescales from its
// innovations: HDOP (VDOP, or 1.5 HDOP, vertically) times a user range error.
// Velocity from RMC/VTG speed and course.
#include "drivers/gps/gps_fix.hpp"
#include "estimator/ekf/aiding/gnss_observation.hpp"

namespace sinu::board {

struct GnssSigmaConfig {
  double uere_m = 2.5;            // user equivalent range error for sigma = DOP * UERE
  double min_sigma_m = 0.2;      // floor: below it time tagging (20 ms at 10 m/s) and lever arms dominate
  double velocity_sigma_m_s = 0.2;
  double position_sigma_scale = 1.0;  // the stated sigma (GST, DOP x UERE) times this (diagnose's noise finding)
  double no_dop_sigma_m = 5.0;    // neither GST nor HDOP
  double rtk_fixed_sigma_m = 0.02, rtk_float_sigma_m = 0.5;  // no GST, GGA quality 4 / 5 (twice that vertically)
};

/// False when the fix has no usable position.
bool gnss_from_fix(const drivers::GpsFix& fix, const GnssSigmaConfig& cfg, est::GnssObservation& out);

}  // namespace sinu::board
