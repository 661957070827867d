// The vertical check (estimator/nav/vertical_check.hpp) on synthetic fixes:
// a white height noise like a receiver's (0.8 m at 5 Hz, the simulator's), a
// climb, and what must not trip it: noise, an INS within a metre per second,
// a receiver's height step.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "estimator/nav/vertical_check.hpp"

namespace sinu::est {
namespace {

constexpr double kRate_hz = 5.0;
constexpr double kHeightSigma_m = 0.8;
constexpr double kClimb_m_s = 3.0;  // up: vd = -3

struct CheckRun {
  int fired = 0;
  double first_fire_t = NAN;
  VerticalRate rate;
};

/// 10 minutes of fixes; the INS's vd off by vd_error from t_error on; a
/// height step of `step_m` at t = 300 s.
CheckRun run(double vd_error, double t_error, double step_m, unsigned seed, double rate_hz = kRate_hz) {
  VerticalCheck check;
  check.configure({});
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, kHeightSigma_m);
  CheckRun r;
  for (int k = 0; k < static_cast<int>(600.0 * rate_hz); ++k) {
    const double t = k / rate_hz;
    const double h = kClimb_m_s * t + noise(rng) + (t >= 300.0 ? step_m : 0.0);
    const double vd_ins = -kClimb_m_s + (t >= t_error ? vd_error : 0.0);
    VerticalRate out;
    if (check.push(t, h, vd_ins, 0.1, out)) {
      if (r.fired++ == 0) {
        r.first_fire_t = t;
        r.rate = out;
      }
    }
  }
  return r;
}

TEST(VerticalCheck, NoiseAndAnInsWithinAMetrePerSecondNeverTripIt) {
  // 20 runs of 3000 fixes each: a false alarm rate of even 1e-4 per fix would show.
  for (unsigned seed = 1; seed <= 20; ++seed) {
    EXPECT_EQ(run(0.0, 0.0, 0.0, seed).fired, 0) << seed;
    EXPECT_EQ(run(0.7, 100.0, 0.0, seed).fired, 0) << seed;  // under the 1 m/s floor
  }
}

TEST(VerticalCheck, AReceiversHeightStepIsNoRate) {
  // A step between two fixes, the INS right: the heights are no line while
  // the step is in the window (a step small enough to pass as noise moves the
  // rate by less than the 1 m/s floor).
  for (const double step_m : {2.0, 5.0, 10.0, 30.0, -10.0})
    for (unsigned seed = 1; seed <= 20; ++seed) EXPECT_EQ(run(0.0, 0.0, step_m, seed).fired, 0) << step_m << " m, " << seed;
}

TEST(VerticalCheck, AnInsThatRunsAwayIsCaughtAndGivenTheHeightsRate) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const CheckRun r = run(3.0, 200.0, 0.0, seed);
    ASSERT_GE(r.fired, 1) << seed;
    // persist_s (2 s) after the window first shows it; an 8-s window needs a
    // third of itself with the error first: within 6 s.
    EXPECT_GT(r.first_fire_t, 200.0);
    EXPECT_LT(r.first_fire_t, 206.0) << seed;
    // The heights' rate, in the climb: -3 m/s down, its sigma from the fit
    // (0.8 m over 8 s of 5-Hz fixes: ~0.05 m/s); 4 sigma.
    EXPECT_NEAR(r.rate.vd_m_s, -kClimb_m_s, 4.0 * r.rate.sigma_m_s) << seed;
    EXPECT_LT(r.rate.sigma_m_s, 0.2);
    EXPECT_GT(r.rate.disagreement_m_s, 1.0);
  }
}

TEST(VerticalCheck, AOneHertzReceiverIsCheckedToo) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    EXPECT_EQ(run(0.0, 0.0, 0.0, seed, 1.0).fired, 0) << seed;
    const CheckRun r = run(3.0, 200.0, 0.0, seed, 1.0);
    ASSERT_GE(r.fired, 1) << seed;
    EXPECT_LT(r.first_fire_t, 210.0) << seed;  // 8-s window, 2 s to persist
    EXPECT_NEAR(r.rate.vd_m_s, -kClimb_m_s, 4.0 * r.rate.sigma_m_s) << seed;
  }
}

TEST(VerticalCheck, TimeGoingBackStartsOverAndBadNumbersAreIgnored) {
  VerticalCheck check;
  check.configure({});
  VerticalRate out;
  // An INS 5 m/s off over level heights, but the clock goes back after 8
  // fixes (1.4 s, short of the 2 s a window must span): the window starts over.
  for (int k = 0; k < 8; ++k) EXPECT_FALSE(check.push(10.0 + k * 0.2, 0.0, 5.0, 0.1, out));
  EXPECT_FALSE(check.push(10.5, 0.0, 5.0, 0.1, out));
  EXPECT_FALSE(check.push(NAN, 0.0, 5.0, 0.1, out));
  EXPECT_FALSE(check.push(10.6, NAN, 5.0, 0.1, out));
  double fired_at = NAN;
  for (int k = 1; k < 100 && std::isnan(fired_at); ++k)
    if (check.push(10.5 + k * 0.2, 0.0, 5.0, 0.1, out)) fired_at = 10.5 + k * 0.2;
  // Eleven fixes from the restart (min_span_s 2 s), then persist_s 2 s: 4.2 s
  // after the restart. Before the restart nothing counts.
  EXPECT_NEAR(fired_at, 10.5 + 4.2, 0.21);
}

}  // namespace
}  // namespace sinu::est
