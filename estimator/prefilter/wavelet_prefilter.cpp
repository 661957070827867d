#include "estimator/prefilter/wavelet_prefilter.hpp"

namespace sinu::est {

std::unique_ptr<ImuPrefilter> make_wavelet_prefilter(wavelet::WaveletKind kind, int levels,
                                                     const DetailThresholds& keep_above) {
  return wavelet::with_denoiser(kind, levels, [&]<class Denoiser>() -> std::unique_ptr<ImuPrefilter> {
    return std::make_unique<WaveletPrefilter<Denoiser>>(keep_above);
  });
}

}  // namespace sinu::est
