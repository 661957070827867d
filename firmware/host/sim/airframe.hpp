#pragma once
// What flies a simulated trajectory (`sinu simulate flight --airframe`).
//   fixed-wing: the paper's UAV: a take-off roll, 33-47 m/s, coordinated
//     turns banked 15-35 deg, climbs and descents at its angle of attack; it
//     taxis straight below 5 m/s.
//   multirotor: a survey: vertical take-off and landing, legs at 3-8 m/s
//     nose first, tilted into its speed (0.6 deg per m/s: the drag the tilt
//     balances), coordinated turns banked 5-15 deg (8-50 deg/s), hover stops,
//     climbs and descents with the body level. What it cannot do: yaw on the
//     spot or fly sideways (the body's x axis follows the track).
#include <array>
#include <cstdint>
#include <string_view>

namespace sinu::sim {

enum class Airframe : std::uint8_t { FixedWing, Multirotor };

inline constexpr std::array<const char*, 2> kAirframeNames{"fixed-wing", "multirotor"};

inline const char* airframe_name(Airframe a) { return kAirframeNames[static_cast<std::size_t>(a)]; }

inline bool airframe_from_name(std::string_view name, Airframe& out) {
  for (std::size_t i = 0; i < kAirframeNames.size(); ++i) {
    if (name == kAirframeNames[i]) {
      out = static_cast<Airframe>(i);
      return true;
    }
  }
  return false;
}

/// Below this ground speed it does not turn: the coordinated turn's rate, g tan(bank) / V, has no limit at
/// V = 0 (a fixed wing taxis straight; a multirotor turns only in its legs, this is a guard).
inline double min_turn_speed_m_s(Airframe a) { return a == Airframe::FixedWing ? 5.0 : 0.5; }

}  // namespace sinu::sim
