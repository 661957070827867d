#pragma once
// Streaming wavelet denoiser: decompose to level `Levels`, drop every detail,
// reconstruct from the approximation (the paper's pre-filter, section 2).
// One sample in, one sample out, delayed by the compile-time constant kDelay:
// step(x[n]) returns y[n - kDelay].
//
// Equivalence (host_tests/estimator/test_wavelet_pywt.cpp): away from the
// start-up transient, y equals pywt's waverec(wavedec(x, mode='symmetric')
// with the details zeroed) where x[0] is the first sample after reset(): the
// decimation grid of every level is anchored at that sample (phase 0).
//
// Work per sample: level j runs once every 2^j samples (one analysis and one
// synthesis pair); the worst sample (every 2^Levels-th) runs all levels, so it
// is O(Levels) with a bound fixed at compile time. State is a few fixed arrays.
#include <array>
#include <cstddef>

#include "estimator/wavelet/lifting_chain.hpp"

namespace sinu::est::wavelet {

inline constexpr int kMaxLevels = 6;

template <LiftingScheme W, int Levels>
  requires(Levels >= 1 && Levels <= kMaxLevels)
class WaveletDenoiser {
 public:
  using Analysis = LiftingChain<W, LiftDirection::Analysis>;
  using Synthesis = LiftingChain<W, LiftDirection::Synthesis>;
  static constexpr int kLevels = Levels;

  /// Delay in input samples. A level with inner delay D (in its own pair
  /// rate) delays its input by 1 (waiting for the odd sample of a pair)
  /// plus 2 * (analysis look-ahead + D + synthesis look-ahead).
  static constexpr int kDelay = [] {
    int d = 0;
    for (int j = 0; j < Levels; ++j) d = 1 + 2 * (Analysis::kLookAhead + d + Synthesis::kLookAhead);
    return d;
  }();

  /// Inner levels pair their input so that the pair grid matches pywt's:
  /// the analysis output s_lift[m - lag] is pywt's a[m - lag + pywt_shift].
  static constexpr bool kInnerStartsOdd = ((W::pywt_shift - Analysis::kLookAhead) % 2 + 2) % 2 == 1;

  explicit WaveletDenoiser(double initial = 0.0) { reset(initial); }

  /// Forgets the past and primes every register as if the input had been
  /// `initial` forever (no start-up ramp from zero). The priming length is a
  /// multiple of 2^Levels, so the decimation phase after reset is the same.
  void reset(double initial) {
    for (std::size_t j = 0; j < levels_.size(); ++j) {
      Level& level = levels_[j];
      level.analysis.clear();
      level.synthesis.clear();
      level.held_even = 0.0;
      level.pending_odd = 0.0;
      level.expecting_odd = j > 0 && kInnerStartsOdd;
    }
    for (int n = 0; n < kPrimingSamples; ++n) step(initial);
  }

  /// Takes x[n], returns y[n - kDelay].
  double step(double x) { return process<0>(x); }

 private:
  // Every register is overwritten after (delay + filter support) samples; 2x
  // the delay plus two full periods covers both, rounded to whole periods.
  static constexpr int kPeriod = 1 << Levels;
  static constexpr int kPrimingSamples = ((2 * kDelay + 2 * kPeriod) / kPeriod + 1) * kPeriod;

  struct Level {
    Analysis analysis;
    Synthesis synthesis;
    double held_even = 0.0;    // first sample of the pair being collected
    double pending_odd = 0.0;  // second sample of the last reconstructed pair
    bool expecting_odd = false;
  };

  template <int J>
  double process(double x) {
    Level& level = levels_[static_cast<std::size_t>(J)];
    if (!level.expecting_odd) {
      level.held_even = x;
      level.expecting_odd = true;
      return level.pending_odd;
    }
    level.expecting_odd = false;
    const EvenOdd lifted = level.analysis.push({level.held_even, x});
    double approx = W::scale * lifted.even;  // the detail (lifted.odd) is dropped
    if constexpr (J + 1 < Levels) approx = process<J + 1>(approx);
    const EvenOdd rebuilt = level.synthesis.push({approx / W::scale, 0.0});
    level.pending_odd = rebuilt.odd;
    return rebuilt.even;
  }

  std::array<Level, static_cast<std::size_t>(Levels)> levels_{};
};

}  // namespace sinu::est::wavelet
