// The multirotor's manoeuvres (airframe.hpp, manoeuvre_planner.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "firmware/host/sim/manoeuvre_planner.hpp"

namespace sinu::sim {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kVertical_rad = std::numbers::pi / 2.0;  // the flight path of a vertical climb
constexpr double kGroundStill_s = 60.0;
constexpr double kClimbRate_m_s = 2.0, kDescentRate_m_s = 1.5;
constexpr double kMinAgl_m = 20.0, kMaxAgl_m = 80.0, kLandedAgl_m = 1.0;
constexpr double kMinLeg_m_s = 3.0, kMaxLeg_m_s = 8.0;
constexpr double kTiltPerSpeed_rad = 0.6 * kDeg;  // nose down per m/s of horizontal speed
constexpr double kTurnRamp_s = 2.0, kHeightRamp_s = 3.0;

// pitch = gamma + alpha (true_motion.cpp): a level body on any flight path has
// alpha = -gamma; then tilted nose down into its horizontal speed.
double alpha_rad(double speed_m_s, double gamma_rad) {
  return -kTiltPerSpeed_rad * speed_m_s * std::cos(gamma_rad) - gamma_rad;
}

// Stop, turn the track down, descend at kDescentRate_m_s, stop; and a margin.
double landing_s(double agl_m) {
  return 5.0 + 3.0 + std::max(0.0, agl_m - kLandedAgl_m) / kDescentRate_m_s + 3.0 + 20.0;
}
}  // namespace

Primitive ManoeuvrePlanner::multirotor(double ramp_s, double hold_s, double speed_m_s, double gamma_rad,
                                       double bank_rad, const char* name) const {
  return {ramp_s, hold_s, speed_m_s, gamma_rad, bank_rad, alpha_rad(speed_m_s, gamma_rad), name};
}

void ManoeuvrePlanner::plan_multirotor(const PlannerInput& in) {
  const double left = in.end_s - in.t_s;
  if (phase_ == Phase::Ground) {
    push(multirotor(0.0, std::min(kGroundStill_s, 0.2 * left), 0.0, 0.0, 0.0, "on ground"));
    phase_ = Phase::Climbout;
    return;
  }
  if (phase_ == Phase::Climbout) {
    // The track turned vertical while still, straight up, stop, the track level again.
    const double target_agl = rng_.uniform(30.0, 60.0);
    push(multirotor(1.0, 0.0, 0.0, kVertical_rad, 0.0, "on ground"));
    push(multirotor(3.0, std::max(0.0, target_agl / kClimbRate_m_s - 3.0), kClimbRate_m_s, kVertical_rad, 0.0,
                    "vertical climb"));
    push(multirotor(3.0, 2.0, 0.0, kVertical_rad, 0.0, "hover"));
    push(multirotor(2.0, 1.0, 0.0, 0.0, 0.0, "hover"));
    phase_ = Phase::Cruise;
    return;
  }
  if (phase_ != Phase::Cruise) {  // landed: on the ground to the end
    push(multirotor(2.0, std::max(1.0, left), 0.0, -kVertical_rad, 0.0, "on ground"));
    phase_ = Phase::Done;
    return;
  }
  if (left < landing_s(in.height_agl_m) + 120.0) {
    const double dh = std::max(0.0, in.height_agl_m - kLandedAgl_m);
    push(multirotor(3.0, 2.0, 0.0, 0.0, 0.0, "stop"));
    push(multirotor(2.0, 1.0, 0.0, -kVertical_rad, 0.0, "hover"));
    push(multirotor(2.0, std::max(0.0, dh / kDescentRate_m_s - 2.0), kDescentRate_m_s, -kVertical_rad, 0.0,
                    "vertical descent"));
    push(multirotor(2.0, 1.0, 0.0, -kVertical_rad, 0.0, "landing"));
    phase_ = Phase::FinalDescent;
    return;
  }
  // Turns and height changes fly at a leg's speed: from a hover, a leg first.
  if (speed_m_s_ < kMinLeg_m_s) {
    push(multirotor(4.0, rng_.uniform(10.0, 40.0), rng_.uniform(kMinLeg_m_s, kMaxLeg_m_s), 0.0, 0.0, "leg"));
    return;
  }
  const double u = rng_.uniform();
  if (u < 0.30) {
    push(multirotor(2.0, rng_.uniform(20.0, 90.0), speed_m_s_, 0.0, 0.0, "leg"));
  } else if (u < 0.62) {
    const double bank = rng_.signed_uniform(5.0, 15.0) * kDeg;
    const double turn = rng_.uniform(60.0, 180.0) * kDeg;
    plan_turn(bank, turn, kTurnRamp_s, alpha_rad(speed_m_s_, 0.0));
  } else if (u < 0.72) {
    push(multirotor(3.0, rng_.uniform(5.0, 20.0), 0.0, 0.0, 0.0, "hover"));
  } else if (u < 0.86) {
    double target = rng_.uniform(kMinAgl_m + 5.0, kMaxAgl_m - 5.0);
    if (std::abs(target - in.height_agl_m) < 10.0)
      target = in.height_agl_m > 0.5 * (kMinAgl_m + kMaxAgl_m) ? in.height_agl_m - 20.0 : in.height_agl_m + 20.0;
    const double dh = target - in.height_agl_m;
    const double gamma = std::copysign(rng_.uniform(5.0, 15.0) * kDeg, dh);
    const double hold = std::max(0.0, std::abs(dh) / (speed_m_s_ * std::sin(std::abs(gamma))) - kHeightRamp_s);
    push(multirotor(kHeightRamp_s, hold, speed_m_s_, gamma, 0.0, dh > 0 ? "climb" : "descent"));
    push(multirotor(kHeightRamp_s, 2.0, speed_m_s_, 0.0, 0.0, "level off"));
  } else {
    push(multirotor(rng_.uniform(3.0, 6.0), rng_.uniform(10.0, 30.0), rng_.uniform(kMinLeg_m_s, kMaxLeg_m_s), 0.0,
                    0.0, "speed change"));
  }
}

}  // namespace sinu::sim
