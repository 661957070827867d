#pragma once
// Flight phases from a navigation solution (nav.csv rows at 10 Hz): where a
// model fails often depends on what the vehicle was doing. Thresholds are
// those of a UAV at 30-40 m/s: a coordinated turn of 20 deg bank is ~5 deg/s.
#include <array>
#include <cstddef>

namespace sinu::diagnose {

enum class Phase : std::size_t { Straight, Turning, Climbing, SpeedChange, Ground };
inline constexpr std::size_t kPhaseCount = 5;
inline constexpr std::array<const char*, kPhaseCount> kPhaseNames = {"straight", "turning", "climbing/descending",
                                                                     "speed change", "ground/slow"};

struct PhaseThresholds {
  double turn_rate_deg_s = 3.0;
  double vertical_speed_m_s = 1.5;
  double accel_m_s2 = 0.4;
  double slow_speed_m_s = 5.0;
};

/// One phase from yaw rate [deg/s], vertical speed, along-track acceleration and ground speed.
Phase classify_phase(double yaw_rate_deg_s, double vd_m_s, double accel_m_s2, double speed_m_s,
                     const PhaseThresholds& th = {});

}  // namespace sinu::diagnose
