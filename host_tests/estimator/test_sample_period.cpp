// The IMU's nominal interval from its stamps (estimator/nav/sample_period.hpp).
#include <gtest/gtest.h>

#include <random>

#include "estimator/nav/sample_period.hpp"

namespace sinu::est {
namespace {

// A 100-Hz IMU stamped at receipt, +-4 ms of uniform jitter: the intervals
// run from 2 to 18 ms. The period stays at 10 ms (the mean of 50 intervals
// of 3.3 ms RMS scatter: 0.5 ms), where a reset on any interval below half
// of it had read 2 ms.
TEST(SamplePeriod, JitteredStampsKeepTheTruePeriod) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> jitter(-0.004, 0.004);
  SamplePeriod p;
  double prev = 0.0;
  double lowest = 1.0;
  for (int k = 1; k <= 20000; ++k) {
    const double t = 0.01 * k + jitter(rng);
    p.add(t - prev);
    prev = t;
    if (k > 100) lowest = std::min(lowest, p.seconds());
  }
  EXPECT_NEAR(p.seconds(), 0.010, 0.0015);
  EXPECT_GT(lowest, 0.0085);  // never collapsed
}

// A gap does not move it; a rate that really doubles is followed within
// 20 intervals (restarted from their mean), and a first interval that was a
// gap is forgotten the same way.
TEST(SamplePeriod, GapsDoNotMoveItARealRateChangeDoes) {
  SamplePeriod p;
  p.add(1.5);  // the first interval: a gap before the stream settled
  for (int k = 0; k < 20; ++k) p.add(0.01);
  EXPECT_NEAR(p.seconds(), 0.01, 1e-12);
  p.add(2.0);  // a 2-s gap
  EXPECT_NEAR(p.seconds(), 0.01, 1e-12);
  for (int k = 0; k < 19; ++k) p.add(0.004);
  EXPECT_GT(p.seconds(), 0.008);  // not yet
  p.add(0.004);
  EXPECT_NEAR(p.seconds(), 0.004, 1e-12);
  p.add(0.0);   // a repeated stamp
  p.add(-0.1);  // time going backwards
  EXPECT_NEAR(p.seconds(), 0.004, 1e-12);
}

}  // namespace
}  // namespace sinu::est
