#pragma once
// Streaming wavelet denoiser: decompose to level `Levels`, drop the details,
// reconstruct from the approximation (the paper's pre-filter, section 2).
// One sample in, one sample out, delayed by the compile-time constant kDelay:
// step(x[n]) returns y[n - kDelay].
//
// Details are dropped unless keep_details_above() set a threshold for their
// level: a detail coefficient larger than it is kept (hard thresholding,
// Donoho & Johnstone 1994). At a few sigma of the sensor's noise at that
// level, noise is still removed as the paper does, while motion faster than
// the approximation's band (a spin's onset, a flip) passes: the level-L
// approximation alone smears it and the attitude integrated from it is wrong
// for as long as the smear lasts. Default: every threshold infinite (the
// paper's approximation); all zero: perfect reconstruction, delayed.
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
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

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

  /// Delay in input samples of a denoiser with `levels` levels. A level with
  /// inner delay D (in its own pair rate) delays its input by 1 (waiting for
  /// the odd sample of a pair) plus 2 * (analysis look-ahead + D + synthesis
  /// look-ahead).
  static constexpr int delay_of(int levels) {
    int d = 0;
    for (int j = 0; j < levels; ++j) d = 1 + 2 * (Analysis::kLookAhead + d + Synthesis::kLookAhead);
    return d;
  }
  static constexpr int kDelay = delay_of(Levels);

  /// Detail magnitude above which a detail of level j + 1 (index 0: the
  /// finest) is kept, in the input's unit (the details are orthonormal: white
  /// noise of sigma s gives details of sigma s at every level).
  using Thresholds = std::array<double, static_cast<std::size_t>(Levels)>;
  static constexpr Thresholds drop_all() {
    Thresholds t{};
    t.fill(std::numeric_limits<double>::infinity());
    return t;
  }

  /// Inner levels pair their input so that the pair grid matches pywt's:
  /// the analysis output s_lift[m - lag] is pywt's a[m - lag + pywt_shift].
  static constexpr bool kInnerStartsOdd = ((W::pywt_shift - Analysis::kLookAhead) % 2 + 2) % 2 == 1;

  explicit WaveletDenoiser(double initial = 0.0) { reset(initial); }

  void keep_details_above(const Thresholds& t) { keep_above_ = t; }

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
      level.details.fill(0.0);
      level.next_detail = 0;
    }
    for (int n = 0; n < kPrimingSamples; ++n) step(initial);
  }

  /// Takes x[n], returns y[n - kDelay].
  double step(double x) {
    auto ignore = [](int, double) {};
    return process<0>(x, ignore);
  }

  /// The same, and calls on_detail(level, d) for every detail coefficient
  /// the step computes (level 1: the finest), before thresholding: what a
  /// bench session measures the noise's details with.
  template <class OnDetail>
  double step(double x, OnDetail&& on_detail) {
    return process<0>(x, on_detail);
  }

 private:
  // Every register is overwritten after (delay + filter support) samples; 2x
  // the delay plus two full periods covers both, rounded to whole periods.
  static constexpr int kPeriod = 1 << Levels;
  static constexpr int kPrimingSamples = ((2 * kDelay + 2 * kPeriod) / kPeriod + 1) * kPeriod;

  // A level's kept detail waits for its approximation to come back from the
  // coarser levels: delay_of(levels below it) pairs, at most delay_of(Levels - 1).
  static constexpr std::size_t kMaxDetailWait = static_cast<std::size_t>(delay_of(Levels - 1)) + 1;

  struct Level {
    Analysis analysis;
    Synthesis synthesis;
    double held_even = 0.0;    // first sample of the pair being collected
    double pending_odd = 0.0;  // second sample of the last reconstructed pair
    bool expecting_odd = false;
    std::array<double, kMaxDetailWait> details{};  // kept details, oldest at next_detail
    std::size_t next_detail = 0;
  };

  template <int J, class OnDetail>
  double process(double x, OnDetail& on_detail) {
    Level& level = levels_[static_cast<std::size_t>(J)];
    if (!level.expecting_odd) {
      level.held_even = x;
      level.expecting_odd = true;
      return level.pending_odd;
    }
    level.expecting_odd = false;
    const EvenOdd lifted = level.analysis.push({level.held_even, x});
    double approx = W::scale * lifted.even;
    const double detail = lifted.odd / W::scale;
    on_detail(J + 1, detail);
    double kept = std::abs(detail) > keep_above_[static_cast<std::size_t>(J)] ? detail : 0.0;
    if constexpr (J + 1 < Levels) {
      approx = process<J + 1>(approx, on_detail);
      // Swap the new detail for the one that waited as long as the approximation did.
      constexpr std::size_t kWait = static_cast<std::size_t>(delay_of(Levels - J - 1));
      std::swap(kept, level.details[level.next_detail]);
      level.next_detail = (level.next_detail + 1) % kWait;
    }
    const EvenOdd rebuilt = level.synthesis.push({approx / W::scale, kept * W::scale});
    level.pending_odd = rebuilt.odd;
    return rebuilt.even;
  }

  std::array<Level, static_cast<std::size_t>(Levels)> levels_{};
  Thresholds keep_above_ = drop_all();
};

}  // namespace sinu::est::wavelet
