// Properties of the streaming denoiser that need no pywt: constants pass
// unchanged, Haar reproduces block means exactly (level 1-6), the delay and
// phase survive reset(), every detail kept is a perfect reconstruction,
// thresholds at a few noise sigmas remove noise as the approximation does
// while a spin's onset passes, and the denoiser never touches the heap.
#include <gtest/gtest.h>

#include <algorithm>
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

TEST(WaveletDenoiser, KeepingEveryDetailReconstructsTheInputDelayed) {
  // Analysis then synthesis is the identity for every lifting scheme; with
  // every detail kept (threshold 0) only the delay remains. The details of
  // level j wait for the approximation to return from the coarser levels: a
  // wrong wait shows here as a mismatch at once.
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> x(2000);
  for (double& v : x) v = noise(rng);
  for (WaveletKind kind : kAll) {
    for (int levels = 1; levels <= kMaxLevels; ++levels) {
      with_denoiser(kind, levels, [&]<class Denoiser>() {
        Denoiser denoiser(x.front());
        typename Denoiser::Thresholds zero{};
        denoiser.keep_details_above(zero);
        denoiser.reset(x.front());  // the thresholds survive a reset
        double worst = 0.0;
        for (std::size_t n = 0; n < x.size(); ++n) {
          const double y = denoiser.step(x[n]);
          if (n >= static_cast<std::size_t>(Denoiser::kDelay)) {
            worst = std::max(worst, std::abs(y - x[n - static_cast<std::size_t>(Denoiser::kDelay)]));
          }
        }
        // Rounding through up to 6 levels of lifting steps with coefficients
        // up to 16 (db4): 1e-11 on unit-variance data, not 1e-15.
        EXPECT_LT(worst, 1e-11) << wavelet_name(kind) << " level " << levels;
      });
    }
  }
}

TEST(WaveletDenoiser, DetailsAboveTheNoiseLetASpinsOnsetThrough) {
  // A gyro at 100 Hz with 0.01 rad/s white noise; at 3 s the unit starts a
  // yaw spin at pi rad/s within 50 ms (a quadcopter's yaw flip), stops at 5 s.
  // Level-3 db4 keeps 0-6 Hz. Thresholds at 4 sigma of the noise (details of
  // white noise have the noise's sigma at every level: orthonormal wavelet).
  constexpr double dt = 0.01, sigma = 0.01, rate = 3.141592653589793;
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<double> truth(800), x(800);
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = static_cast<double>(n) * dt;
    const double up = std::clamp((t - 3.0) / 0.05, 0.0, 1.0), down = std::clamp((t - 5.0) / 0.05, 0.0, 1.0);
    truth[n] = rate * (up - down);
    x[n] = truth[n] + noise(rng);
  }
  using D = WaveletDenoiser<Db4, 3>;
  D approximation(0.0), thresholded(0.0);
  D::Thresholds four_sigma;
  four_sigma.fill(4.0 * sigma);
  thresholded.keep_details_above(four_sigma);
  const auto delay = static_cast<std::size_t>(D::kDelay);
  double angle_true = 0.0, angle_a = 0.0, angle_t = 0.0, worst_a = 0.0, worst_t = 0.0;
  double noise_a = 0.0, noise_t = 0.0;  // squared error at rest (first 2.5 s)
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double ya = approximation.step(x[n]), yt = thresholded.step(x[n]);
    if (n < delay) continue;
    const std::size_t k = n - delay;
    angle_true += truth[k] * dt;
    angle_a += ya * dt;
    angle_t += yt * dt;
    worst_a = std::max(worst_a, std::abs(angle_a - angle_true));
    worst_t = std::max(worst_t, std::abs(angle_t - angle_true));
    if (k < 250) {
      noise_a += (ya - truth[k]) * (ya - truth[k]);
      noise_t += (yt - truth[k]) * (yt - truth[k]);
    }
  }
  // The approximation smears each edge over its ~0.3-s impulse response: the
  // integrated yaw is off while it does (0.021 rad, 1.2 deg, measured; a
  // 1-deg floor asserts the case is real). Kept details pass the edge: what
  // remains is the noise integrated over the edge (0.004 rad measured); 3x
  // smaller is the claim.
  EXPECT_GT(worst_a, 0.0175);
  EXPECT_LT(worst_t, worst_a / 3.0);
  // At rest, 4-sigma thresholds keep 6e-5 of the noise details: the output
  // noise is the approximation's (within 10 %: a kept outlier or two).
  EXPECT_LT(noise_t, 1.1 * noise_a);
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
