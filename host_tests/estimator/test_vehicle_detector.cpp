// vehicle = auto: a ground vehicle is recognised by its body-frame velocity
// (no sideways, no vertical component while it drives and turns), an
// aircraft never is (angle of attack, crab, a multirotor's tilt), and a wrong
// guess is taken back when the constraint fails.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "estimator/ins/rotation.hpp"
#include "estimator/nav/vehicle_detector.hpp"

namespace sinu::test {
namespace {

constexpr double kDt = 0.025;  // 40 Hz
constexpr double kDeg = std::numbers::pi / 180.0;

/// A vehicle circling at `speed` (a full turn every `turn_period_s`) whose
/// velocity in the body frame is (speed, lateral, vertical): the body's
/// heading leads or trails the track by the crab angle, its pitch the
/// flight path by the angle of attack.
est::NavState state_at(double t, double speed, double lateral_m_s, double vertical_m_s, double turn_period_s) {
  const double track = 2.0 * std::numbers::pi * t / turn_period_s;
  const double crab = std::atan2(lateral_m_s, speed), aoa = std::atan2(vertical_m_s, speed);
  est::NavState nav;
  nav.t_s = t;
  nav.q_nb = est::quat_from_euler(0.0, aoa, track - crab);
  const Eigen::Vector3d v_b(speed, lateral_m_s, vertical_m_s);
  nav.v_n_m_s = nav.C_nb() * v_b;
  return nav;
}

est::VehicleGuess run(double seconds, double speed, double lateral, double vertical, double& decided_at) {
  est::VehicleDetector d;
  d.configure({});
  for (double t = 0.0; t < seconds; t += kDt) d.add(state_at(t, speed, lateral, vertical, 60.0), kDt, true);
  decided_at = d.decided_at_s();
  return d.guess();
}

TEST(VehicleDetector, ACarThatDrivesAndTurnsIsAGroundVehicleAfterHalfAMinute) {
  double at = 0.0;
  // 10 m/s, 0.1 m/s of sideways and vertical velocity: what the real car's
  // solution shows (0.05-0.1 vertical, 0.1-0.4 lateral, docs/experiments.md).
  EXPECT_EQ(run(120.0, 10.0, 0.1, 0.1, at), est::VehicleGuess::Ground);
  // Not before the 30 s of motion the evidence needs (a quarter turn takes 15 s here).
  EXPECT_GE(at, 30.0 - 1e-9);
  EXPECT_LT(at, 31.0);
}

TEST(VehicleDetector, AircraftAreNeverTakenForGroundVehicles) {
  double at = 0.0;
  // A fixed wing at 40 m/s and 2 deg angle of attack: 1.4 m/s along body z.
  EXPECT_EQ(run(600.0, 40.0, 0.0, 40.0 * std::tan(2.0 * kDeg), at), est::VehicleGuess::Undecided);
  // Crabbing into a crosswind: 2 m/s sideways, 0.2 m/s along z.
  EXPECT_EQ(run(600.0, 25.0, 2.0, 0.2, at), est::VehicleGuess::Undecided);
  // A multirotor pitched 10 deg into 8 m/s of forward flight.
  EXPECT_EQ(run(600.0, 8.0, 0.0, 8.0 * std::tan(10.0 * kDeg), at), est::VehicleGuess::Undecided);
  // Flying sideways, rolled 10 deg into it: the sideways mounting's test sees its body z too.
  EXPECT_EQ(run(600.0, 0.2, 8.0, 8.0 * std::tan(10.0 * kDeg), at), est::VehicleGuess::Undecided);
}

// A unit mounted sideways (its x axis to the car's right) on a car circling
// at 10 m/s, whose solution's heading is `heading_error_deg` off (after the
// course check: 5-20 deg) and 0.1 m/s vertical: its body velocity lies along
// body y, turned by the heading error.
est::VehicleDetector sideways_car(double heading_error_deg) {
  est::VehicleDetector d;
  d.configure({});
  for (double t = 0.0; t < 120.0; t += kDt) {
    const double track = 2.0 * std::numbers::pi * t / 60.0;
    est::NavState nav;
    nav.t_s = t;
    nav.q_nb = est::quat_from_euler(0.0, 0.0, track - std::numbers::pi / 2.0 + heading_error_deg * kDeg);
    nav.v_n_m_s = Eigen::Vector3d(10.0 * std::cos(track), 10.0 * std::sin(track), 0.1);
    d.add(nav, kDt, true);
  }
  return d;
}

TEST(VehicleDetector, AUnitMountedSidewaysIsFoundWithItsLateralAxis) {
  for (const double error_deg : {0.0, 7.0, -15.0}) {
    const est::VehicleDetector d = sideways_car(error_deg);
    EXPECT_EQ(d.guess(), est::VehicleGuess::Ground) << error_deg;
    EXPECT_EQ(d.lateral_axis(), 0) << "the body x is across the car";
    // Across the motion's own axis: the constant heading error turns it, it adds nothing across.
    EXPECT_LT(d.lateral_rms_m_s(), 0.05) << error_deg;
  }
  // As the contract mounts it, the lateral axis stays body y.
  est::VehicleDetector d;
  d.configure({});
  for (double t = 0.0; t < 120.0; t += kDt) d.add(state_at(t, 10.0, 0.1, 0.1, 60.0), kDt, true);
  EXPECT_EQ(d.guess(), est::VehicleGuess::Ground);
  EXPECT_EQ(d.lateral_axis(), 1);
}

TEST(VehicleDetector, StraightOrSlowOrUnaidedMotionIsNoEvidence) {
  est::VehicleDetector d;
  d.configure({});
  // A car-like body velocity, but along a straight line: no turn, no decision.
  for (double t = 0.0; t < 300.0; t += kDt) d.add(state_at(t, 10.0, 0.0, 0.0, 1e9), kDt, true);
  EXPECT_EQ(d.guess(), est::VehicleGuess::Undecided);
  // Turning at walking pace (below 3 m/s), or without GNSS (dead reckoning): not counted.
  d.configure({});
  for (double t = 0.0; t < 300.0; t += kDt) d.add(state_at(t, 2.0, 0.0, 0.0, 60.0), kDt, true);
  for (double t = 0.0; t < 300.0; t += kDt) d.add(state_at(t, 10.0, 0.0, 0.0, 60.0), kDt, false);
  EXPECT_EQ(d.guess(), est::VehicleGuess::Undecided);
  EXPECT_EQ(d.moving_s(), 0.0);
}

TEST(VehicleDetector, AnEarlyMisfitIsForgottenAndAFailedConstraintRevertsForGood) {
  est::VehicleDetector d;
  d.configure({});
  // The first minute with a poor heading (1 m/s sideways), then car-like: the
  // 60-s memory lets the later evidence decide.
  double t = 0.0;
  for (; t < 60.0; t += kDt) d.add(state_at(t, 10.0, 1.0, 0.1, 60.0), kDt, true);
  EXPECT_EQ(d.guess(), est::VehicleGuess::Undecided);
  for (; t < 300.0 && d.guess() == est::VehicleGuess::Undecided; t += kDt)
    d.add(state_at(t, 10.0, 0.05, 0.05, 60.0), kDt, true);
  ASSERT_EQ(d.guess(), est::VehicleGuess::Ground);
  // Then the constraint is rejected in 6 of every 10 updates for 10 s: it does not hold.
  for (int k = 0; k < 120; ++k) d.on_constraint(t + 0.1 * k, k % 10 < 4);
  EXPECT_EQ(d.guess(), est::VehicleGuess::Reverted);
  // And a rejection now and then (1 in 10) leaves a ground vehicle alone.
  d.configure({});
  for (t = 0.0; t < 120.0; t += kDt) d.add(state_at(t, 10.0, 0.05, 0.05, 60.0), kDt, true);
  ASSERT_EQ(d.guess(), est::VehicleGuess::Ground);
  for (int k = 0; k < 300; ++k) d.on_constraint(t + 0.1 * k, k % 10 != 0);
  EXPECT_EQ(d.guess(), est::VehicleGuess::Ground);
}

}  // namespace
}  // namespace sinu::test
