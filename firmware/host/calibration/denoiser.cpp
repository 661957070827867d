#include "firmware/host/calibration/denoiser.hpp"

#include <cmath>

#include "estimator/wavelet/denoiser_select.hpp"
#include "firmware/host/dataset/quantile.hpp"

namespace sinu::calibration {

namespace wv = sinu::est::wavelet;

Denoiser no_denoiser() {
  Denoiser d;
  d.name = "none";
  d.apply = [](std::span<const double> x, double) { return std::vector<double>(x.begin(), x.end()); };
  return d;
}

namespace {

// Runs the streaming denoiser over a whole series and removes its delay:
// out[n] = y[n + delay], with the filter primed by the first sample and fed
// the last sample for `delay` extra steps (the same end handling as
// `sinu denoise`), so out is time-aligned with x and as long.
template <class Filter>
std::vector<double> denoise_series(std::span<const double> x) {
  std::vector<double> out;
  if (x.empty()) return out;
  out.reserve(x.size());
  Filter filter(x.front());
  const auto delay = static_cast<std::size_t>(Filter::kDelay);
  for (std::size_t n = 0; n < x.size() + delay; ++n) {
    const double y = filter.step(x[n < x.size() ? n : x.size() - 1]);
    if (n >= delay) out.push_back(y);
  }
  return out;
}

// The details of every level as the streaming denoiser computes them (the same
// pairing phase), and their robust sigma: median |d| / 0.6745 (Gaussian).
template <class Filter>
std::vector<double> detail_sigma_series(std::span<const double> x) {
  std::vector<std::vector<double>> magnitude(static_cast<std::size_t>(Filter::kLevels));
  if (x.empty()) return std::vector<double>(magnitude.size(), 0.0);
  Filter filter(x.front());
  for (double v : x) {
    filter.step(v, [&](int level, double d) { magnitude[static_cast<std::size_t>(level - 1)].push_back(std::abs(d)); });
  }
  std::vector<double> sigma;
  for (auto& m : magnitude) sigma.push_back(dataset::quantile(std::move(m), 0.5) / 0.6744897501960817);
  return sigma;
}

}  // namespace

bool make_wavelet_denoiser(const std::string& wavelet, int levels, Denoiser& out, std::string& why) {
  const auto kind = wv::parse_wavelet(wavelet);
  if (!kind) {
    why = "--wavelet '" + wavelet + "': unknown wavelet (haar, db2, db4, cdf53, cdf97)";
    return false;
  }
  if (levels < 1 || levels > wv::kMaxLevels) {
    why = "--levels " + std::to_string(levels) + ": must be 1.." + std::to_string(wv::kMaxLevels);
    return false;
  }
  out.name = std::string("wavelet ") + wv::wavelet_name(*kind) + ", level-" + std::to_string(levels) +
             " approximation";
  out.wavelet = wv::wavelet_name(*kind);
  out.levels = levels;
  const wv::WaveletKind k = *kind;
  out.apply = [k, levels](std::span<const double> x, double) {
    return wv::with_denoiser(k, levels, [&]<class Filter>() { return denoise_series<Filter>(x); });
  };
  out.detail_sigma = [k, levels](std::span<const double> x) {
    return wv::with_denoiser(k, levels, [&]<class Filter>() { return detail_sigma_series<Filter>(x); });
  };
  return true;
}

}  // namespace sinu::calibration
