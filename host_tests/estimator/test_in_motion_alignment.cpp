// In-motion alignment (OBA) against the analytic flight and a straight,
// level, constant-velocity trajectory (alignment_run.hpp): accuracy with
// perfect sensors, consistency of the reported sigmas with noise and biases,
// yaw observability, window restarts, no heap allocation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "host_tests/estimator/alignment_run.hpp"
#include "host_tests/support/alloc_counter.hpp"

namespace sinu::test {
namespace {

// 1. Perfect sensors, started in the middle of the flight (200 s and 600 s
// after its start: both in a coordinated turn of ~5 deg/s, 25 deg bank).
TEST(InMotionAlignment, PerfectSensorsInTurns) {
  for (const double start : {200.0, 600.0}) {
    const Outcome o = run(flight(), kFlightStart + start, 20.0, calibrated(), Errors{});
    print(start < 300.0 ? "perfect, turn at 200 s" : "perfect, turn at 600 s", o);
    EXPECT_NEAR(o.first_solution_s, 3.0, 1e-9);  // min_window_s
    // The brief's bounds. Measured: 6e-4 deg tilt, 6e-4 deg yaw (trapezoidal
    // integrals at 100 Hz, the height-slope fit of the curved climb).
    EXPECT_LT(o.max_tilt_err_rad, 0.05 * kDeg);
    EXPECT_LT(o.max_yaw_err_rad, 0.2 * kDeg);
    // With 0.1 m/s GNSS velocity noise modelled, the yaw sigma passes 3 deg
    // after 6.6 / 6.8 s (the turn rotates the centripetal acceleration by
    // ~0.6 rad by then).
    ASSERT_GE(o.yaw_observable_s, 0.0);
    EXPECT_LE(o.yaw_observable_s, 10.0);
  }
}

// 1b. A lever arm of a metre: the antenna's rotation-induced velocity moves
// to the body side (beta = C (alpha + C_b0_b (w x l)) + c); left out, it is
// an error of ~0.1 m/s in the turn.
TEST(InMotionAlignment, LeverArm) {
  const Eigen::Vector3d lever(0.4, -0.3, -1.0);
  const Trajectory tr = make_flight(lever);
  est::InMotionAlignmentConfig cfg = calibrated();
  cfg.lever_arm_b_m = lever;
  const Outcome with = run(tr, kFlightStart + 200.0, 20.0, cfg, Errors{});
  const Outcome without = run(tr, kFlightStart + 200.0, 20.0, calibrated(), Errors{});
  print("lever configured", with);
  print("lever ignored", without);
  // Same bounds as without a lever (measured the same 1e-3 deg level).
  EXPECT_LT(with.max_tilt_err_rad, 0.05 * kDeg);
  EXPECT_LT(with.max_yaw_err_rad, 0.2 * kDeg);
  EXPECT_GT(without.max_tilt_err_rad + without.max_yaw_err_rad, 5.0 * (with.max_tilt_err_rad + with.max_yaw_err_rad));
}

// 2. The brief's noise: GNSS 0.1 m/s and 1 m, gyro bias 0.2 deg/s and
// accelerometer bias 0.05 m/s^2 per axis, consumer-MEMS white noise; the
// module configured with those statistics. In the two turns: errors within
// 3 sigma. A Gaussian error exceeds 3 sigma on one of 3 axes in 0.8 % of
// the solutions; the first-order model is ~10-25 % optimistic after 15 s
// (below), so up to 3 % is allowed, and no error beyond 4.5 sigma.
TEST(InMotionAlignment, NoisyErrorsWithinThreeSigma) {
  int checked = 0, beyond = 0;
  double worst = 0.0;
  for (const double start : {200.0, 600.0}) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
      const Outcome o = run(flight(), kFlightStart + start, 30.0, matched(realistic(seed)), realistic(seed));
      char name[48];
      std::snprintf(name, sizeof name, "noisy, turn at %.0f s, seed %u", start, seed);
      print(name, o);
      checked += o.checked;
      beyond += o.beyond_3_sigma;
      worst = std::max({worst, o.max_tilt_ratio, o.max_yaw_ratio});
    }
  }
  std::printf("%d of %d solutions beyond 3 sigma, worst %.2f sigma\n", beyond, checked, worst);
  EXPECT_GT(checked, 1500);
  EXPECT_LE(beyond, checked * 3 / 100);
  EXPECT_LT(worst, 4.5);
}

// 2b. With that noise, yaw is reported observable within 10 s of starting at
// a turn entry (the turn rate changes, which separates yaw from the roll-axis
// gyro bias), and its error is then within 3 sigma. (In a steady turn the
// two are confounded, yaw ~ b g / (V w^2), and it takes 13-25 s.)
TEST(InMotionAlignment, NoisyYawObservableAtTurnEntry) {
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const Outcome o = run(flight(), kFlightStart + 180.0, 20.0, matched(realistic(seed)), realistic(seed));
    print("noisy, turn entry at 180 s", o);
    ASSERT_GE(o.yaw_observable_s, 0.0);
    EXPECT_LE(o.yaw_observable_s, 10.0);
    EXPECT_LT(o.max_yaw_ratio, 3.0);
    // The gyro bias estimate (once yaw is known): measured up to 3.1 sigma
    // over the ~120 correlated solutions of a run.
    EXPECT_LT(o.max_gyro_bias_ratio, 4.0);
  }
}

// 2c. The sigmas are honest: over 24 runs started every 5 s through turns
// and turn reversals, the RMS of error / sigma at fixed times, first and
// second window (max_window_s 20 s). Measured 0.7-1.2; [0.6, 1.4] leaves
// the sampling error of 24 runs (+-14 %) on either side.
// The cross test presets skip it (100 s under qemu): the single-run tests
// above check the same arithmetic on the board's instruction set.
TEST(InMotionAlignment, SigmasAreHonestOverManyRuns) {
  constexpr int kRuns = 24;
  for (const double from : {80.0, 480.0}) {
    Eigen::Matrix<double, Outcome::kSnaps, 2> sum2 = Eigen::Matrix<double, Outcome::kSnaps, 2>::Zero();
    for (int k = 0; k < kRuns; ++k) {
      const Errors e = realistic(static_cast<unsigned>(k + 1));
      sum2 += run(flight(), kFlightStart + from + 5.0 * k, 30.0, matched(e), e).z.cwiseAbs2();
    }
    const Eigen::Matrix<double, Outcome::kSnaps, 2> rms = (sum2 / kRuns).cwiseSqrt();
    for (int q = 0; q < Outcome::kSnaps; ++q) {
      std::printf("runs from %.0f s, %4.1f s after the start: RMS error/sigma tilt %.2f yaw %.2f\n", from,
                  4.0 + 5.0 * q, rms(q, 0), rms(q, 1));
      EXPECT_GT(rms.row(q).minCoeff(), 0.6);
      EXPECT_LT(rms.row(q).maxCoeff(), 1.4);
    }
  }
}

// 3. Straight, level, constant-velocity flight: the pairs are collinear
// with gravity's integral, so yaw is never reported observable; tilt is.
TEST(InMotionAlignment, StraightLevelFlightHasNoYaw) {
  const Trajectory tr = straight_level(70.0);
  const Outcome perfect = run(tr, kFlightStart, 70.0, est::InMotionAlignmentConfig{}, Errors{});
  print("straight, perfect", perfect);
  EXPECT_LT(perfect.yaw_observable_s, 0.0);
  EXPECT_GT(perfect.final_yaw_sigma_rad, 30.0 * kDeg);   // no information but the Earth rate
  EXPECT_LT(perfect.max_tilt_err_rad, 0.01 * kDeg);       // measured 1e-5 deg
  EXPECT_EQ(perfect.restarts, 3);                         // 70 s in windows of 20 s
  EXPECT_LE(perfect.max_window_s, 20.0 + 1e-9);
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Outcome noisy = run(tr, kFlightStart, 70.0, matched(realistic(seed)), realistic(seed));
    print("straight, noisy", noisy);
    EXPECT_LT(noisy.yaw_observable_s, 0.0);
    EXPECT_LT(noisy.max_tilt_ratio, 3.0);       // magnitude against the RSS sigma
    EXPECT_LT(noisy.max_tilt_err_rad, 2.0 * kDeg);  // accelerometer bias b / g = 0.3 deg, gyro bias over 20 s
  }
}

// 4. Window restarts: a GNSS gap longer than max_gnss_gap_s, an IMU gap, and
// the window cap; a short GNSS gap does not restart.
TEST(InMotionAlignment, RestartsOnGaps) {
  const est::InMotionAlignmentConfig cfg = calibrated();
  const double t0 = kFlightStart + 200.0;
  Gaps long_gap;
  long_gap.gnss_from_s = t0 + 8.05;
  long_gap.gnss_to_s = t0 + 9.55;  // 1.5 s without epochs
  const Outcome a = run(flight(), t0, 18.0, cfg, Errors{}, long_gap);
  EXPECT_EQ(a.restarts, 1);
  EXPECT_NEAR(a.first_after_gap_s, 3.05, 1e-6);  // the next epoch (9.6 s) starts a window: min_window_s
  EXPECT_NEAR(a.window_after_gap_s, 3.0, 1e-6);
  EXPECT_LT(a.max_tilt_err_rad, 0.05 * kDeg);    // and is as good as the first

  Gaps short_gap;
  short_gap.gnss_from_s = t0 + 8.05;
  short_gap.gnss_to_s = t0 + 8.55;  // 0.5 s: the window goes on
  const Outcome b = run(flight(), t0, 18.0, cfg, Errors{}, short_gap);
  EXPECT_EQ(b.restarts, 0);
  EXPECT_NEAR(b.first_after_gap_s, 0.05, 1e-6);  // the next epoch
  EXPECT_NEAR(b.window_after_gap_s, 8.6, 1e-6);

  Gaps imu_gap;
  imu_gap.imu_from_s = t0 + 8.02;
  imu_gap.imu_to_s = t0 + 8.32;  // 0.3 s of IMU lost (> max_imu_gap_s)
  const Outcome c = run(flight(), t0, 18.0, cfg, Errors{}, imu_gap);
  EXPECT_EQ(c.restarts, 1);

  const Outcome d = run(flight(), t0, 65.0, cfg, Errors{});
  EXPECT_EQ(d.restarts, 3);  // windows of 20 s
  EXPECT_LE(d.max_window_s, 20.0 + 1e-9);
  EXPECT_LT(d.max_tilt_err_rad, 0.05 * kDeg);
  EXPECT_LT(d.max_yaw_err_rad, 0.2 * kDeg);
}

// 5. No heap allocation in add_imu / add_gnss: a whole noisy run (windows,
// solutions, feedback, a restart) inside one allocation scope.
TEST(InMotionAlignment, NoHeapAllocation) {
  const Trajectory& tr = flight();  // built before the scope
  const Errors e = realistic(1);
  AllocationScope scope;
  const Outcome o = run(tr, kFlightStart + 200.0, 30.0, matched(e), e);
  EXPECT_EQ(scope.count(), 0u);
  EXPECT_GT(o.solutions, 200);  // the loop really solved (not a vacuous zero)
  EXPECT_EQ(o.restarts, 1);     // and restarted at the 20 s cap
}

// Not a check: the table behind the numbers in docs/in_motion_alignment.md
// (run with --gtest_also_run_disabled_tests).
TEST(InMotionAlignment, DISABLED_Survey) {
  char name[64];
  for (double t = 20.0; t < 640.0; t += 20.0) {
    std::snprintf(name, sizeof name, "perfect calibrated %.0f", t);
    print(name, run(flight(), kFlightStart + t, 30.0, calibrated(), Errors{}));
    std::snprintf(name, sizeof name, "perfect default %.0f", t);
    print(name, run(flight(), kFlightStart + t, 30.0, est::InMotionAlignmentConfig{}, Errors{}));
    for (unsigned seed = 1; seed <= 3; ++seed) {
      std::snprintf(name, sizeof name, "noisy matched %.0f s%u", t, seed);
      print(name, run(flight(), kFlightStart + t, 30.0, matched(realistic(seed)), realistic(seed)));
    }
  }
}

}  // namespace
}  // namespace sinu::test
