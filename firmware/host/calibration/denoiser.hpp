#pragma once
// The denoise step before GM/AR fitting is pluggable: calibrate takes any
// function from a series (and its sample rate) to the denoised series. The
// paper's choice is the wavelet level-3 approximation (issue 4). `None` passes
// the series through (--no-denoise).
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace sinu::calibration {

/// A detail larger than this many sigma of the bench's noise at its level is
/// motion, and the flight keeps it (estimator/wavelet/wavelet_denoiser.hpp).
/// 4 sigma: 6e-5 of Gaussian noise details pass (one in 16000); a spin's or
/// a flip's onset is hundreds of sigma.
inline constexpr double kKeepDetailsAboveSigma = 4.0;

struct Denoiser {
  std::string name;        // "none" or e.g. "wavelet db4, 3 levels"
  std::string wavelet;     // empty for none
  int levels = 0;
  std::function<std::vector<double>(std::span<const double> x, double sample_rate_hz)> apply;
  /// The noise's sigma in the details of each level (index 0: the finest),
  /// robust (median |d| / 0.6745: a knock on the bench does not count); empty for none.
  std::function<std::vector<double>(std::span<const double> x)> detail_sigma;
};

Denoiser no_denoiser();

/// The streaming wavelet denoiser of estimator/wavelet (issue 4) over a whole
/// series, delay removed; false with `why` for an unknown name or level count.
bool make_wavelet_denoiser(const std::string& wavelet, int levels, Denoiser& out, std::string& why);

}  // namespace sinu::calibration
