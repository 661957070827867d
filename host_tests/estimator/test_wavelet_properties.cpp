// Properties of the streaming denoiser that need no pywt: constants pass
// unchanged, Haar reproduces block means exactly (level 1-6), the delay and
// phase survive reset(), and the denoiser never touches the heap.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "estimator/wavelet/denoiser_select.hpp"
#include "host_tests/support/alloc_counter.hpp"

namespace {

using namespace sinu::est::wavelet;

constexpr WaveletKind kAll[] = {WaveletKind::Haar, WaveletKind::Db2, WaveletKind::Db4, WaveletKind::Cdf53,
                                WaveletKind::Cdf97};

TEST(WaveletDenoiser, ConstantPassesUnchangedAtEveryLevel) {
  // Every wavelet here has at least one vanishing moment: the details of a
  // constant are zero, so approximation-only reconstruction is exact.
  // reset(c) primes the registers, so there is no start-up ramp at all.
  for (WaveletKind kind : kAll) {
    for (int levels = 1; levels <= kMaxLevels; ++levels) {
      with_denoiser(kind, levels, [&]<class Denoiser>() {
        const double g = -9.80665;
        Denoiser denoiser(g);
        double worst = 0.0;
        for (int n = 0; n < 500; ++n) worst = std::max(worst, std::abs(denoiser.step(g) - g));
        // 1e-12 relative: a few dozen rounding errors through the lifting steps
        // (db4 has coefficients up to 16, hence not 1e-15).
        EXPECT_LT(worst, 1e-12 * std::abs(g)) << wavelet_name(kind) << " level " << levels;
      });
    }
  }
}

TEST(WaveletDenoiser, HaarIsTheBlockMeanWithItsDelay) {
  // Haar approximation at level J is the mean of each block of 2^J samples
  // (blocks start at the first sample after reset); the delay is 2^J - 1.
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> x(1024);
  for (double& v : x) v = noise(rng);
  for (int levels = 1; levels <= kMaxLevels; ++levels) {
    with_denoiser(WaveletKind::Haar, levels, [&]<class Denoiser>() {
      const std::size_t block = std::size_t{1} << levels;
      EXPECT_EQ(Denoiser::kDelay, static_cast<int>(block) - 1);
      Denoiser denoiser;
      for (std::size_t n = 0; n < x.size(); ++n) {
        const double y = denoiser.step(x[n]);
        if (n < block) continue;
        const std::size_t src = n - static_cast<std::size_t>(Denoiser::kDelay);
        const std::size_t start = src - src % block;
        double mean = 0.0;
        for (std::size_t i = start; i < start + block; ++i) mean += x[i];
        mean /= static_cast<double>(block);
        ASSERT_NEAR(y, mean, 1e-13) << "level " << levels << " n " << n;  // rounding of 2^J terms
      }
    });
  }
}

TEST(WaveletDenoiser, ResetRestoresPhaseAndDelay) {
  // The same input after reset() gives the same output as a fresh object,
  // whatever had been fed before (odd counts included).
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> x(300);
  for (double& v : x) v = noise(rng);
  for (WaveletKind kind : kAll) {
    with_denoiser(kind, 3, [&]<class Denoiser>() {
      Denoiser fresh(1.0), reused(5.0);
      for (int n = 0; n < 37; ++n) reused.step(noise(rng));
      reused.reset(1.0);
      for (double v : x) ASSERT_EQ(fresh.step(v), reused.step(v)) << wavelet_name(kind);
    });
  }
}

TEST(WaveletDenoiser, Db4Level3DelayIsKnown) {
  // analysis and synthesis look ahead 2 pairs each: 9, 27, 63 samples.
  EXPECT_EQ((WaveletDenoiser<Db4, 1>::kDelay), 9);
  EXPECT_EQ((WaveletDenoiser<Db4, 3>::kDelay), 63);
  // The impulse response's centre of mass sits near the delay (db4 is
  // nearly but not exactly linear-phase): within a quarter of the 8-sample
  // decimation period, averaged over the 8 impulse phases.
  double centre = 0.0;
  for (int phase = 0; phase < 8; ++phase) {
    WaveletDenoiser<Db4, 3> d;
    double m0 = 0.0, m1 = 0.0;
    for (int n = 0; n < 300; ++n) {
      const double y = d.step(n == 64 + phase ? 1.0 : 0.0);
      m0 += y;
      m1 += y * (n - 64 - phase);
    }
    EXPECT_NEAR(m0, 1.0, 1e-12);  // DC gain 1 (the approximation keeps the mean)
    centre += m1 / m0 / 8.0;
  }
  EXPECT_NEAR(centre, 63.0, 8.0);
}

TEST(WaveletDenoiser, AllocatesNothing) {
  for (WaveletKind kind : kAll) {
    for (int levels = 1; levels <= kMaxLevels; ++levels) {
      with_denoiser(kind, levels, [&]<class Denoiser>() {
        sinu::test::AllocationScope scope;
        Denoiser denoiser(0.5);
        double sum = 0.0;
        for (int n = 0; n < 2000; ++n) sum += denoiser.step(std::sin(0.1 * n));
        denoiser.reset(0.0);
        EXPECT_EQ(scope.count(), 0u) << wavelet_name(kind) << " level " << levels;
        EXPECT_TRUE(std::isfinite(sum));
      });
    }
  }
}

}  // namespace
