#include "firmware/host/diagnose/flight_phase.hpp"

#include <cmath>

namespace sinu::diagnose {

Phase classify_phase(double yaw_rate_deg_s, double vd_m_s, double accel_m_s2, double speed_m_s,
                     const PhaseThresholds& th) {
  if (speed_m_s < th.slow_speed_m_s) return Phase::Ground;
  if (std::abs(yaw_rate_deg_s) > th.turn_rate_deg_s) return Phase::Turning;
  if (std::abs(vd_m_s) > th.vertical_speed_m_s) return Phase::Climbing;
  if (std::abs(accel_m_s2) > th.accel_m_s2) return Phase::SpeedChange;
  return Phase::Straight;
}

}  // namespace sinu::diagnose
