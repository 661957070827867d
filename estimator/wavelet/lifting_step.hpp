#pragma once
// One lifting step of a two-channel filter bank (Daubechies & Sweldens 1998).
// The signal is split into pairs e[m] = x[2m], o[m] = x[2m+1]; m counts pairs.
//   Predict: o[m] += sum_t coeff[t] * e[m + first_offset + t]
//   Update:  e[m] += sum_t coeff[t] * o[m + first_offset + t]
// A positive offset reaches into the future: a streaming implementation waits
// for it (look-ahead), which is where the denoiser's delay comes from.
#include <algorithm>
#include <array>
#include <cstddef>

namespace sinu::est::wavelet {

enum class LiftKind { Predict, Update };

inline constexpr std::size_t kMaxLiftTaps = 2;

struct LiftingStep {
  LiftKind kind;
  int first_offset;  // pair offset of coeff[0]
  int taps;          // 1..kMaxLiftTaps
  std::array<double, kMaxLiftTaps> coeff;

  constexpr int last_offset() const { return first_offset + taps - 1; }
  /// Pairs this step must wait for: its largest future offset.
  constexpr int look_ahead() const { return std::max(0, last_offset()); }
  /// Past pairs it reads.
  constexpr int history() const { return std::max(0, -first_offset); }
};

/// What a wavelet supplies (see wavelet_bases.hpp): lifting steps in analysis
/// order, the final scaling s[m] = scale * e[m], and where the lifting
/// approximation sits against pywt's: s[m] = pywt a[m + pywt_shift].
template <class W>
concept LiftingScheme = requires {
  W::steps;
  { W::scale } -> std::convertible_to<double>;
  { W::pywt_shift } -> std::convertible_to<int>;
  { W::name } -> std::convertible_to<const char*>;
};

/// Sum of the steps' look-aheads: pairs between a pair's arrival and its
/// analysis output (the inverse chain has the same lag).
template <LiftingScheme W>
constexpr int chain_look_ahead() {
  int lag = 0;
  for (const LiftingStep& s : W::steps) lag += s.look_ahead();
  return lag;
}

/// Shift-register length that serves every step of W.
template <LiftingScheme W>
constexpr std::size_t chain_register_length() {
  int r = 1;
  for (const LiftingStep& s : W::steps) r = std::max(r, s.look_ahead() + s.history() + 1);
  return static_cast<std::size_t>(r);
}

}  // namespace sinu::est::wavelet
