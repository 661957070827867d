#pragma once
// The NMEA 0183 sentences an autopilot or logger that takes an external GPS
// reads, written from the navigation solution (no allocation):
//   RMC  time, status A/V, position, speed and course over ground, date
//   GGA  time, position, fix quality, satellites, HDOP, altitude MSL, geoid
//   GST  time, error statistics from the solution's position covariance
// A sentence carries a position only for a fix (aligned and not lost, see
// nmea_fix_valid); otherwise its fields are empty, as a receiver without a
// fix writes them, so no reader can take a solution the filter disowns.
// Without UTC the time and date fields are empty too.
//
// Resolution, chosen so that rounding never shows next to the filter's own
// uncertainty (a uniform rounding step q adds q/sqrt(12) of noise):
//   time       hhmmss.sss      1 ms, the solution's stamp (10 ms would misplace
//                              a position by 0.3 m at 30 m/s, more than its sigma)
//   lat, lon   6 decimals of a minute: 1.85 mm (0.5 mm rms); a reader that
//              differences 5 Hz positions for velocity sees 9 mm/s steps,
//              well under the filter's ~0.05 m/s velocity sigma (5 decimals: 9 cm/s)
//   altitude, geoid separation   1 mm (climb rate from 5 Hz differences: 5 mm/s steps)
//   speed      0.001 knot = 0.5 mm/s;  course  0.01 deg (5 mm/s across track at 30 m/s)
//   GST        metres to 1 mm; ellipse orientation to 0.1 deg
// The longest GGA is 88 bytes with CR LF, over NMEA 0183's 82, as with
// receivers in high-precision mode; gpsd and the project's parser take it.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "firmware/board/nav_solution.hpp"

namespace sinu::board {

/// Talker ID: GP (GPS) for readers that accept nothing else, GN (multi-GNSS).
enum class NmeaTalker : std::uint8_t { GP, GN };
const char* to_string(NmeaTalker talker);
/// "GP" or "GN"; false for anything else.
bool parse_talker(std::string_view text, NmeaTalker& out);

/// Room one sentence needs, '$' to LF plus the writer's NUL (the longest is 88).
inline constexpr std::size_t kNmeaSentenceMax = 96;
/// Room one epoch (RMC, GGA, GST) needs.
inline constexpr std::size_t kNmeaEpochMax = 3 * kNmeaSentenceMax;

/// A receiver would call this a fix: aligned, and not flagged lost.
bool nmea_fix_valid(const NavSolution& nav);

// Each writes one sentence, "*hh" and CR LF into `out` and returns its length
// (without the NUL that follows it); 0 if `out` is shorter than kNmeaSentenceMax.
std::size_t write_rmc(const NavSolution& nav, NmeaTalker talker, std::span<char> out);
std::size_t write_gga(const NavSolution& nav, NmeaTalker talker, std::span<char> out);
std::size_t write_gst(const NavSolution& nav, NmeaTalker talker, std::span<char> out);
/// RMC, GGA, GST in a receiver's order (RMC first brings the date before the
/// position, GST last ends the cycle for gpsd's and our fix assembler).
/// Returns the total length; 0 if `out` is shorter than kNmeaEpochMax.
std::size_t write_nmea_epoch(const NavSolution& nav, NmeaTalker talker, std::span<char> out);

}  // namespace sinu::board
