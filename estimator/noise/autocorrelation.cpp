#include "estimator/noise/autocorrelation.hpp"

#include <algorithm>
#include <complex>
#include <unsupported/Eigen/FFT>

namespace sinu::noise {

namespace {

// Below this many lags the direct sum beats the FFT (measured: the FFT of a
// 2^21 series costs about as much as ~60 direct lags).
constexpr std::size_t kDirectMaxLags = 32;

void scale_lags(std::vector<double>& r, std::size_t n, AcfScale scale) {
  for (std::size_t k = 0; k < r.size(); ++k) {
    const std::size_t divisor = scale == AcfScale::Biased ? n : n - k;
    r[k] /= static_cast<double>(divisor);
  }
}

}  // namespace

std::vector<double> autocorrelation_direct(std::span<const double> x, std::size_t max_lag, AcfScale scale) {
  const std::size_t n = x.size();
  if (n == 0) return {};
  max_lag = std::min(max_lag, n - 1);
  std::vector<double> r(max_lag + 1, 0.0);
  for (std::size_t k = 0; k <= max_lag; ++k) {
    double s = 0.0;
    for (std::size_t i = k; i < n; ++i) s += x[i] * x[i - k];
    r[k] = s;
  }
  scale_lags(r, n, scale);
  return r;
}

std::vector<double> autocorrelation_fft(std::span<const double> x, std::size_t max_lag, AcfScale scale) {
  const std::size_t n = x.size();
  if (n == 0) return {};
  max_lag = std::min(max_lag, n - 1);
  std::size_t nfft = 1;
  while (nfft < 2 * n) nfft <<= 1;
  std::vector<double> padded(nfft, 0.0);
  std::copy(x.begin(), x.end(), padded.begin());
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, padded);
  for (auto& c : spectrum) c = std::complex<double>(std::norm(c), 0.0);
  std::vector<double> circular;
  fft.inv(circular, spectrum);
  std::vector<double> r(circular.begin(), circular.begin() + static_cast<std::ptrdiff_t>(max_lag + 1));
  scale_lags(r, n, scale);
  return r;
}

std::vector<double> autocorrelation(std::span<const double> x, std::size_t max_lag, AcfScale scale) {
  return max_lag <= kDirectMaxLags ? autocorrelation_direct(x, max_lag, scale)
                                   : autocorrelation_fft(x, max_lag, scale);
}

}  // namespace sinu::noise
