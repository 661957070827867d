// A receiver that holds its course at low speed (u-blox, Unicore, MTK; the
// real quadcopter's log): the same course to the digit while the speed
// changes is a speed without a direction. A course really measured, or a
// speed of zero, is not one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "estimator/earth/geomagnetic_model.hpp"
#include "estimator/nav/course_hold.hpp"
#include "host_tests/estimator/navigator_run.hpp"

namespace sinu::test {
namespace {

Eigen::Vector2d velocity(double speed_m_s, double course_deg) {
  const double c = course_deg * std::numbers::pi / 180.0;
  return speed_m_s * Eigen::Vector2d(std::cos(c), std::sin(c));
}

TEST(CourseHold, TheSameCourseWhileTheSpeedMovesIsHeldFromTheThirdEpoch) {
  est::CourseHold hold;
  hold.configure({});
  // A hover: 0.1-0.26 m/s of lever-arm speed, the course held at 262.58 deg.
  const double speeds[] = {0.12, 0.21, 0.26, 0.10, 0.18, 0.23};
  int held = 0;
  for (int k = 0; k < 6; ++k) {
    const bool h = hold.held(velocity(speeds[k], 262.58));
    EXPECT_EQ(h, k >= 2) << k;  // two repeats before it is believed
    held += h;
  }
  EXPECT_EQ(held, 4);
  // A new course breaks the run.
  EXPECT_FALSE(hold.held(velocity(0.2, 263.0)));
}

TEST(CourseHold, AMeasuredCourseAFastOneOrAStandstillIsNotHeld) {
  est::CourseHold hold;
  hold.configure({});
  // Measured at 1 m/s with 0.05 m/s of noise per axis, written to 0.01 deg:
  // it scatters by degrees and never repeats three times.
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Vector2d v = velocity(1.0, 40.0) + Eigen::Vector2d(noise(rng), noise(rng));
    const double course = std::round(std::atan2(v.y(), v.x()) * 180.0 / std::numbers::pi * 100.0) / 100.0;
    const double speed = std::round(v.norm() / 0.514444 * 1000.0) / 1000.0 * 0.514444;
    EXPECT_FALSE(hold.held(velocity(speed, course))) << k;
  }
  // A straight leg at 15 m/s with a course written to whole degrees repeats it, and that is a measurement.
  hold.configure({});
  for (int k = 0; k < 20; ++k) EXPECT_FALSE(hold.held(velocity(15.0 + 0.01 * k, 40.0)));
  // Standing, the receiver says 0 m/s: no direction is claimed, nothing held.
  hold.configure({});
  for (int k = 0; k < 20; ++k) EXPECT_FALSE(hold.held(velocity(0.0, 0.0)));
}

// A unit standing (or hovering) for two minutes, its receiver reporting
// 0.1-0.3 m/s (a spin's lever arm, noise) along a course it holds east.
// Fused as velocities, those pulled the solution east: the independent
// simulator's quadcopter drifted 2.2 m in 20 s of hover spin. Fused as zero
// within their speed, the solution stays on the fixes. No zero-velocity
// update (an aircraft): only the GNSS says it stands. Bound: 0.5 m, the
// fixes' own sigma (a velocity of 0.2 m/s held for 100 s would be 20 m,
// the fixes pull it back to a few metres).
TEST(CourseHold, AUnitStandingIsNotDraggedAlongTheCourseItsReceiverHolds) {
  FlightProfile still;
  still.stationary = true;
  const std::vector<TruthSample> truth = AnalyticFlight(still).sample(40.0, 120.0);
  std::vector<est::GnssObservation> gnss = AnalyticFlight::gnss(truth, 8, 0.0, Eigen::Vector3d::Zero(), 0.5, 0.1);
  for (std::size_t k = 0; k < gnss.size(); ++k) {
    gnss[k].v_ne_m_s = velocity(0.2 + 0.1 * std::sin(0.7 * static_cast<double>(k)), 90.0);
  }
  // A magnetometer for the heading at rest (the site's field, no noise).
  const est::NavState& start = truth.front().nav;
  const Eigen::Vector3d field_n =
      est::geomag::geomagnetic_field(start.lat_rad, start.lon_rad, start.h_m, 2025.0).b_n_uT;
  std::vector<est::ImuSample> imu;
  for (const TruthSample& s : truth) {
    imu.push_back(s.imu);
    imu.back().has_mag = true;
    imu.back().mag_b_uT = s.nav.C_nb().transpose() * field_n;
  }
  const ScoredRun run(est::NavigatorConfig{}, truth, 40.0, imu, gnss);
  ASSERT_TRUE(run.nav.aligned());
  EXPECT_GT(run.nav.counters().course_held, gnss.size() / 2);
  const std::vector<double>& err = run.stats.pos_err_h;
  const double worst = *std::max_element(err.begin() + std::ssize(err) / 4, err.end());
  std::printf("standing, course held east: worst horizontal error after the first 30 s %.2f m\n", worst);
  EXPECT_LT(worst, 0.5);
}

}  // namespace
}  // namespace sinu::test
