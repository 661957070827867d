// RateTracker: the rates and gaps `sinu inspect dataset` reports.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "firmware/host/dataset/rate_tracker.hpp"

namespace sinu::dataset {
namespace {

/// Arrivals of a receiver at `rate_hz`, each late by a uniform 0..jitter_s
/// (a fixed linear congruential sequence: the test is repeatable).
RateTracker jittered(double rate_hz, double jitter_s, int n, int gap_at = -1, int gap_epochs = 0) {
  RateTracker r;
  std::uint32_t x = 12345u;
  for (int i = 0; i < n; ++i) {
    if (i >= gap_at && i < gap_at + gap_epochs) continue;
    x = x * 1664525u + 1013904223u;
    r.add(1000.0 + i / rate_hz + jitter_s * static_cast<double>(x >> 8) / 16777216.0);
  }
  r.finish();
  return r;
}

TEST(RateTracker, AJitteredTenHertzReceiverIsTenHertz) {
  // Arrivals 0-20 ms late: the median of the first 101 intervals read
  // 9.90 Hz on an independent simulator's receiver. The mean over 6000
  // intervals: 20 ms / (6000 x 0.1 s) of spread at most, 3e-4 relative.
  const RateTracker r = jittered(10.0, 0.02, 6001);
  EXPECT_NEAR(r.nominal_rate_hz(), 10.0, 0.003);
  EXPECT_EQ(r.gaps(), 0u);
}

TEST(RateTracker, AnImuStampedAtReceiptIsOneHundredHertzWithoutGaps) {
  // +-4 ms on every stamp of a 100-Hz IMU: intervals of 2-18 ms. 1.5 times
  // the median read 7,585 gaps and 107 Hz on 69,000 stamps; three
  // interquartile ranges (~4.7 ms) beyond the median hold all of them. A
  // dropped sample (20 +- 8 ms) among them is a gap only where it is longer
  // than that (24 ms): not told apart from the jitter, as it cannot be.
  RateTracker r;
  std::uint32_t x = 777u;
  for (int i = 0; i < 69000; ++i) {
    x = x * 1664525u + 1013904223u;
    r.add(100.0 + i * 0.01 + 0.008 * (static_cast<double>(x >> 8) / 16777216.0 - 0.5));
  }
  r.finish();
  EXPECT_EQ(r.gaps(), 0u);
  EXPECT_NEAR(r.nominal_rate_hz(), 100.0, 0.01);
}

TEST(RateTracker, AGapIsCountedAndLeftOutOfTheRate) {
  // 30 s without fixes in a 5-Hz stream: one gap of 30.2 s, the rate still 5 Hz.
  const RateTracker r = jittered(5.0, 0.01, 3000, 1000, 150);
  EXPECT_EQ(r.gaps(), 1u);
  EXPECT_NEAR(r.longest_gap_s(), 30.2, 0.011);
  EXPECT_NEAR(r.nominal_rate_hz(), 5.0, 0.002);
}

}  // namespace
}  // namespace sinu::dataset
