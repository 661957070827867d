#pragma once
// Lifting factorisations of the five mother wavelets, matched to Debian's
// python3-pywt filter banks (tools/derive_lifting.py derives and verifies
// them; docs/wavelet.md explains the derivation and the names).
//
//   sinu name  pywt name  filter length
//   haar       haar/db1   2
//   db2        db2        4  (Daubechies D4, 2 vanishing moments)
//   db4        db4        8  (Daubechies D8, 4 vanishing moments)
//   cdf53      bior2.2    5/3 (LeGall)
//   cdf97      bior4.4    9/7 (JPEG 2000 irreversible)
//
// Pairing: e[m] = x[2m], o[m] = x[2m+1]. pywt's analysis is
// a[k] = sum_j h[j] x[2k+1-j], so its polyphase row is he = sum h[2i+1] z^-i,
// ho = sum h[2i] z^-i; each table below factors exactly that row and pywt's
// high-pass row (the high-pass fixes the last predict step, which shapes the
// approximation-only synthesis).
#include <array>

#include "estimator/wavelet/lifting_step.hpp"

namespace sinu::est::wavelet {

namespace detail {
inline constexpr double kSqrt2 = 1.4142135623730951;
inline constexpr double kSqrt3 = 1.7320508075688772;
}  // namespace detail

/// Haar: s = (x0 + x1)/sqrt2; d = (x1 - x0)/sqrt2 (pywt 'haar').
struct Haar {
  static constexpr const char* name = "haar";
  static constexpr std::array<LiftingStep, 2> steps{{
      {LiftKind::Update, 0, 1, {1.0, 0.0}},
      {LiftKind::Predict, 0, 1, {-0.5, 0.0}},
  }};
  static constexpr double scale = 1.0 / detail::kSqrt2;
  static constexpr int pywt_shift = 0;
};

/// Daubechies D4 (pywt 'db2'): Daubechies-Sweldens section 7.5 with the
/// update reaching one pair ahead (pywt's odd analysis phase; the paper's
/// errata swaps even and odd).
struct Db2 {
  static constexpr const char* name = "db2";
  static constexpr std::array<LiftingStep, 3> steps{{
      {LiftKind::Predict, 0, 1, {-detail::kSqrt3, 0.0}},
      {LiftKind::Update, 0, 2, {detail::kSqrt3 / 4.0, (detail::kSqrt3 - 2.0) / 4.0}},
      {LiftKind::Predict, -1, 1, {1.0, 0.0}},
  }};
  static constexpr double scale = (detail::kSqrt3 + 1.0) / detail::kSqrt2;
  static constexpr int pywt_shift = 1;
};

/// Daubechies D8 (pywt 'db4'): derived here by the Euclidean algorithm on
/// pywt's polyphase row (tools/derive_lifting.py); no published table used.
struct Db4 {
  static constexpr const char* name = "db4";
  static constexpr std::array<LiftingStep, 5> steps{{
      {LiftKind::Predict, 0, 1, {-3.1029314858303256, 0.0}},
      {LiftKind::Update, 0, 2, {0.29195312600347534, 0.11602641034420537}},
      {LiftKind::Predict, -1, 2, {-5.199491573072545, 16.261203949481885}},
      {LiftKind::Update, 0, 2, {-0.05762194698366655, -0.0006872882928001965}},
      {LiftKind::Predict, -1, 1, {3.0722782814683467, 0.0}},
  }};
  static constexpr double scale = 8.172424199155179;
  static constexpr int pywt_shift = 2;
};

/// CDF 5/3 (pywt 'bior2.2'): predict -1/2, update 1/4, scale sqrt2.
struct Cdf53 {
  static constexpr const char* name = "cdf53";
  static constexpr std::array<LiftingStep, 2> steps{{
      {LiftKind::Predict, 0, 2, {-0.5, -0.5}},
      {LiftKind::Update, -1, 2, {0.25, 0.25}},
  }};
  static constexpr double scale = detail::kSqrt2;
  static constexpr int pywt_shift = 1;
};

/// CDF 9/7 (pywt 'bior4.4'): alpha, beta, gamma, delta of Daubechies-Sweldens
/// section 7.8 to 16 digits (as in ISO 15444-1 F.4). The Euclidean algorithm
/// on pywt's tabulated filters gives the same to 2.5e-12 (pywt stores the
/// taps to ~12 digits); the exact values keep the DC gain exactly 1.
struct Cdf97 {
  static constexpr const char* name = "cdf97";
  static constexpr double alpha = -1.586134342059924;
  static constexpr double beta = -0.052980118572961;
  static constexpr double gamma = 0.882911075530934;
  static constexpr double delta = 0.443506852043971;
  static constexpr std::array<LiftingStep, 4> steps{{
      {LiftKind::Predict, 0, 2, {alpha, alpha}},
      {LiftKind::Update, -1, 2, {beta, beta}},
      {LiftKind::Predict, 0, 2, {gamma, gamma}},
      {LiftKind::Update, -1, 2, {delta, delta}},
  }};
  // sqrt2 / (1 + 2 beta (1 + 2 alpha)): pywt's DC gain sqrt2 for the lowpass
  static constexpr double scale = detail::kSqrt2 / (1.0 + 2.0 * beta * (1.0 + 2.0 * alpha));
  static constexpr int pywt_shift = 2;
};

}  // namespace sinu::est::wavelet
