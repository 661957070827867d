#include "firmware/calibration/denoiser.hpp"

namespace sinu::calib {

Denoiser no_denoiser() {
  Denoiser d;
  d.name = "none";
  d.apply = [](std::span<const double> x, double) { return std::vector<double>(x.begin(), x.end()); };
  return d;
}

bool make_wavelet_denoiser(const std::string& wavelet, int levels, Denoiser& out, std::string& why) {
  (void)out;
  why = "the wavelet denoiser (" + wavelet + ", " + std::to_string(levels) +
        " levels) is not in this build: it arrives with issue 4. Run with --no-denoise to fit the raw "
        "series (the paper warns the fits then mostly describe high-frequency noise)";
  return false;
}

}  // namespace sinu::calib
