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
  // Block (overlap-add in the lag domain) correlation: the sum over n of
  // x(n) x(n+k) is split into blocks of `block` values of n; each block's
  // contribution is the cross-correlation of the block with the block
  // extended by max_lag samples, computed with an FFT of size nfft >=
  // block + max_lag (no circular wrap for k <= max_lag). The spectra add, so
  // one inverse FFT serves all blocks. An FFT of a few times max_lag stays in
  // cache, several times faster than one FFT of the whole (hours-long) series.
  std::size_t nfft = 1;
  while (nfft < 4 * (max_lag + 1)) nfft <<= 1;
  const std::size_t block = nfft - max_lag;
  Eigen::FFT<double> fft;
  std::vector<double> head(nfft), ext(nfft);
  std::vector<std::complex<double>> head_f, ext_f, acc(nfft, 0.0);
  for (std::size_t start = 0; start < n; start += block) {
    const std::size_t head_len = std::min(block, n - start);
    const std::size_t ext_len = std::min(block + max_lag, n - start);
    std::fill(head.begin(), head.end(), 0.0);
    std::fill(ext.begin(), ext.end(), 0.0);
    std::copy_n(x.begin() + static_cast<std::ptrdiff_t>(start), head_len, head.begin());
    std::copy_n(x.begin() + static_cast<std::ptrdiff_t>(start), ext_len, ext.begin());
    fft.fwd(head_f, head);
    fft.fwd(ext_f, ext);
    for (std::size_t i = 0; i < nfft; ++i) acc[i] += std::conj(head_f[i]) * ext_f[i];
  }
  std::vector<double> circular;
  fft.inv(circular, acc);
  std::vector<double> r(circular.begin(), circular.begin() + static_cast<std::ptrdiff_t>(max_lag + 1));
  scale_lags(r, n, scale);
  return r;
}

std::vector<double> autocorrelation(std::span<const double> x, std::size_t max_lag, AcfScale scale) {
  return max_lag <= kDirectMaxLags ? autocorrelation_direct(x, max_lag, scale)
                                   : autocorrelation_fft(x, max_lag, scale);
}

}  // namespace sinu::noise
