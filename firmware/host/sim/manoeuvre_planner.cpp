#include "firmware/host/sim/manoeuvre_planner.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "firmware/host/sim/true_motion.hpp"

namespace sinu::sim {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kGroundStill_s = 60.0;
constexpr double kRotateSpeed_m_s = 22.0;
constexpr double kTakeoffRoll_s = 14.0;
constexpr double kClimbGamma_rad = 8.0 * kDeg;
constexpr double kCruiseAlpha_rad = 3.0 * kDeg;  // pitch above the flight path in the air
constexpr double kMinAgl_m = 100.0, kMaxAgl_m = 300.0;
constexpr double kFinalAgl_m = 30.0;
constexpr double kFinalGamma_rad = -4.0 * kDeg;
constexpr double kFinalSpeed_m_s = 30.0;
constexpr double kHeightRamp_s = 4.0;
}  // namespace

void ManoeuvrePlanner::push(const Primitive& p) {
  if (size_ == queue_.size()) return;  // plans never exceed the queue
  queue_[(head_ + size_) % queue_.size()] = p;
  ++size_;
  speed_m_s_ = p.speed_m_s;
}

void ManoeuvrePlanner::plan_turn(double bank, double turn, double ramp, double alpha) {
  // Heading turned while banked: rate * (hold + ramp) (half of each ramp counts).
  const double rate = coordinated_turn_rate_rad_s(std::abs(bank), speed_m_s_);
  const double hold = std::max(0.0, turn / rate - ramp);
  push({ramp, hold, speed_m_s_, 0.0, bank, alpha, "turn"});
  push({ramp, 2.0, speed_m_s_, 0.0, 0.0, alpha, "roll out"});
}

void ManoeuvrePlanner::plan_height_change(double dh) {
  const double gamma = std::copysign(rng_.uniform(3.0, 7.0) * kDeg, dh);
  const double climb_rate = speed_m_s_ * std::sin(std::abs(gamma));
  const double hold = std::max(0.0, std::abs(dh) / climb_rate - kHeightRamp_s);
  push({kHeightRamp_s, hold, speed_m_s_, gamma, 0.0, kCruiseAlpha_rad, dh > 0 ? "climb" : "descent"});
  push({kHeightRamp_s, 2.0, speed_m_s_, 0.0, 0.0, kCruiseAlpha_rad, "level off"});
}

double ManoeuvrePlanner::final_descent_s(double agl) const {
  const double dh = std::max(0.0, agl - kFinalAgl_m);
  return dh / (kFinalSpeed_m_s * std::sin(-kFinalGamma_rad)) + 4.0 * kHeightRamp_s + 20.0;
}

void ManoeuvrePlanner::plan(const PlannerInput& in) {
  if (airframe_ == Airframe::Multirotor) return plan_multirotor(in);
  const double left = in.end_s - in.t_s;
  switch (phase_) {
    case Phase::Ground:
      push({0.0, std::min(kGroundStill_s, 0.2 * left), 0.0, 0.0, 0.0, 0.0, "on ground"});
      phase_ = Phase::TakeoffRoll;
      return;
    case Phase::TakeoffRoll:
      push({kTakeoffRoll_s, 0.0, kRotateSpeed_m_s, 0.0, 0.0, 0.0, "take-off roll"});
      phase_ = Phase::Climbout;
      return;
    case Phase::Climbout: {
      const double target_agl = rng_.uniform(150.0, 250.0);
      const double speed = 30.0;
      const double climb_rate = speed * std::sin(kClimbGamma_rad);
      push({5.0, std::max(0.0, target_agl / climb_rate - 5.0), speed, kClimbGamma_rad, 0.0, kCruiseAlpha_rad,
            "climb-out"});
      push({6.0, 4.0, 40.0, 0.0, 0.0, kCruiseAlpha_rad, "level off"});
      phase_ = Phase::Cruise;
      return;
    }
    case Phase::Cruise:
      break;
    case Phase::FinalDescent:
    case Phase::Done:
      push({2.0, std::max(1.0, left), speed_m_s_, 0.0, 0.0, kCruiseAlpha_rad, "level approach"});
      phase_ = Phase::Done;
      return;
  }
  // Leave time for the final descent (with a margin for the longest manoeuvre).
  if (left < final_descent_s(in.height_agl_m) + 150.0) {
    const double dh = std::max(0.0, in.height_agl_m - kFinalAgl_m);
    push({8.0, 0.0, kFinalSpeed_m_s, 0.0, 0.0, kCruiseAlpha_rad, "slow down"});
    const double rate = kFinalSpeed_m_s * std::sin(-kFinalGamma_rad);
    push({kHeightRamp_s, std::max(0.0, dh / rate - kHeightRamp_s), kFinalSpeed_m_s, kFinalGamma_rad, 0.0,
          kCruiseAlpha_rad, "final descent"});
    phase_ = Phase::FinalDescent;
    return;
  }
  const double u = rng_.uniform();
  if (u < 0.22) {
    push({2.0, rng_.uniform(20.0, 90.0), speed_m_s_, 0.0, 0.0, kCruiseAlpha_rad, "straight"});
  } else if (u < 0.47) {
    plan_turn(rng_.signed_uniform(15.0, 35.0) * kDeg, rng_.uniform(45.0, 180.0) * kDeg, 3.0, kCruiseAlpha_rad);
  } else if (u < 0.57) {
    plan_turn(rng_.signed_uniform(20.0, 30.0) * kDeg, 2.0 * std::numbers::pi, 3.0, kCruiseAlpha_rad);  // loiter
  } else if (u < 0.67) {
    const double bank = rng_.signed_uniform(20.0, 30.0) * kDeg;  // figure-eight: circle one way, then the other
    const double rate = coordinated_turn_rate_rad_s(std::abs(bank), speed_m_s_);
    const double hold = std::max(0.0, 2.0 * std::numbers::pi / rate - 4.0);
    push({3.0, hold, speed_m_s_, 0.0, bank, kCruiseAlpha_rad, "figure-eight"});
    push({5.0, hold, speed_m_s_, 0.0, -bank, kCruiseAlpha_rad, "figure-eight"});
    push({3.0, 2.0, speed_m_s_, 0.0, 0.0, kCruiseAlpha_rad, "roll out"});
  } else if (u < 0.85) {
    double target = rng_.uniform(kMinAgl_m + 10.0, kMaxAgl_m - 10.0);
    if (std::abs(target - in.height_agl_m) < 40.0)
      target = in.height_agl_m > 0.5 * (kMinAgl_m + kMaxAgl_m) ? in.height_agl_m - 60.0 : in.height_agl_m + 60.0;
    plan_height_change(target - in.height_agl_m);
  } else {
    push({rng_.uniform(10.0, 20.0), rng_.uniform(5.0, 30.0), rng_.uniform(33.0, 47.0), 0.0, 0.0, kCruiseAlpha_rad,
          "speed change"});
  }
}

Primitive ManoeuvrePlanner::next(const PlannerInput& in) {
  if (size_ == 0) plan(in);
  const Primitive p = queue_[head_];
  head_ = (head_ + 1) % queue_.size();
  --size_;
  return p;
}

}  // namespace sinu::sim
