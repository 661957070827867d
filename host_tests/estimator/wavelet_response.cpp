// wavelet_response [CSV]: measures the streaming denoiser's magnitude response
// at 40 Hz for every wavelet and levels 1-4 by feeding unit sines and fitting
// the output's component at the input frequency (least squares, 60 s after
// start-up). The decimated filter is periodically time-varying, so a sine also
// leaks to aliases; the fit keeps only the component at the input frequency,
// averaged over all decimation phases by the long record.
// Writes CSV wavelet,levels,freq_hz,gain and prints the table of docs/wavelet.md.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "estimator/wavelet/denoiser_select.hpp"

namespace {

using namespace sinu::est::wavelet;

constexpr double kRateHz = 40.0;
constexpr int kSettle = 1024;  // > the level-4 delay (db4: 135) plus the filter support
constexpr int kRecord = 2400;  // 60 s

template <class Denoiser>
double gain_at(double f_hz) {
  Denoiser d;
  const double w = 2.0 * std::numbers::pi * f_hz / kRateHz;
  double scc = 0, sss = 0, scs = 0, syc = 0, sys = 0;
  for (int n = 0; n < kSettle + kRecord + Denoiser::kDelay; ++n) {
    const double y = d.step(std::sin(w * n));
    const int k = n - Denoiser::kDelay;  // the input index this output belongs to
    if (k < kSettle) continue;
    const double c = std::cos(w * k), s = std::sin(w * k);
    scc += c * c, sss += s * s, scs += c * s, syc += y * c, sys += y * s;
  }
  const double det = scc * sss - scs * scs;
  if (std::abs(det) < 1e-9 * scc * sss) return std::abs(sys / sss);  // sine degenerate near DC/Nyquist
  const double a = (syc * sss - sys * scs) / det, b = (sys * scc - syc * scs) / det;
  return std::hypot(a, b);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : "wavelet_response.csv";
  std::FILE* csv = std::fopen(path.c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "wavelet_response: cannot write %s\n", path.c_str());
    return 1;
  }
  std::fprintf(csv, "wavelet,levels,freq_hz,gain\n");
  std::printf("| wavelet | level | delay [samples] | -3 dB [Hz] | gain 2 Hz | gain 3 Hz | max gain 12-16 Hz | mean gain 12-16 Hz |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (WaveletKind kind : {WaveletKind::Haar, WaveletKind::Db2, WaveletKind::Db4, WaveletKind::Cdf53, WaveletKind::Cdf97}) {
    for (int levels = 1; levels <= 4; ++levels) {
      with_denoiser(kind, levels, [&]<class Denoiser>() {
        double f3db = -1.0, prev_f = 0.0, prev_g = 1.0, g2 = 0, g3 = 0, band_max = 0, band_sum = 0;
        int band_n = 0;
        for (int i = 1; i <= 398; ++i) {  // 0.05 .. 19.9 Hz
          const double f = 0.05 * i;
          const double g = gain_at<Denoiser>(f);
          std::fprintf(csv, "%s,%d,%.2f,%.6f\n", wavelet_name(kind), levels, f, g);
          if (f3db < 0 && g < std::sqrt(0.5)) f3db = prev_f + (f - prev_f) * (prev_g - std::sqrt(0.5)) / (prev_g - g);
          if (i == 40) g2 = g;
          if (i == 60) g3 = g;
          if (i >= 240 && i <= 320) band_max = std::max(band_max, g), band_sum += g, ++band_n;
          prev_f = f, prev_g = g;
        }
        std::printf("| %s | %d | %d | %.2f | %.3f | %.3f | %.4f | %.4f |\n", wavelet_name(kind), levels,
                    Denoiser::kDelay, f3db, g2, g3, band_max, band_sum / band_n);
      });
    }
  }
  std::fclose(csv);
  return 0;
}
