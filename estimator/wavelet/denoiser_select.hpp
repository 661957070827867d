#pragma once
// The runtime switch over the compile-time denoisers, for the CLI and tools:
// with_denoiser(kind, levels, f) calls f.template operator()<Denoiser>() with
// the WaveletDenoiser<W, levels> instantiation named at run time.
#include <optional>
#include <string_view>

#include "estimator/wavelet/wavelet_bases.hpp"
#include "estimator/wavelet/wavelet_denoiser.hpp"

namespace sinu::est::wavelet {

enum class WaveletKind { Haar, Db2, Db4, Cdf53, Cdf97 };

inline constexpr WaveletKind kDefaultWavelet = WaveletKind::Db4;
inline constexpr int kDefaultLevels = 3;  // 40 Hz / 2^(3+1) = 2.5 Hz (paper, section 2)

/// "haar", "db2", "db4", "cdf53", "cdf97"; nullopt otherwise.
std::optional<WaveletKind> parse_wavelet(std::string_view name);
const char* wavelet_name(WaveletKind kind);

namespace detail {
template <LiftingScheme W, class F>
decltype(auto) with_levels(int levels, F&& f) {
  switch (levels) {
    case 1: return f.template operator()<WaveletDenoiser<W, 1>>();
    case 2: return f.template operator()<WaveletDenoiser<W, 2>>();
    case 3: return f.template operator()<WaveletDenoiser<W, 3>>();
    case 4: return f.template operator()<WaveletDenoiser<W, 4>>();
    case 5: return f.template operator()<WaveletDenoiser<W, 5>>();
    default: return f.template operator()<WaveletDenoiser<W, 6>>();
  }
}
}  // namespace detail

/// levels must be in [1, kMaxLevels] (checked by the caller; 6 otherwise).
template <class F>
decltype(auto) with_denoiser(WaveletKind kind, int levels, F&& f) {
  switch (kind) {
    case WaveletKind::Haar: return detail::with_levels<Haar>(levels, f);
    case WaveletKind::Db2: return detail::with_levels<Db2>(levels, f);
    case WaveletKind::Cdf53: return detail::with_levels<Cdf53>(levels, f);
    case WaveletKind::Cdf97: return detail::with_levels<Cdf97>(levels, f);
    case WaveletKind::Db4: break;
  }
  return detail::with_levels<Db4>(levels, f);
}

}  // namespace sinu::est::wavelet
