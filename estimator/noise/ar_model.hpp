#pragma once
// An autoregressive model in MATLAB's convention (arburg/aryule/arcov):
//   x(n) + a1 x(n-1) + ... + ap x(n-p) = e(n),   e white, variance `variance`
// a = [1, a1, ..., ap]. Its implied autocorrelation and power spectral density
// are what the report draws beside the measured ones.
#include <cstddef>
#include <vector>

namespace sinu::noise {

struct ArModel {
  std::vector<double> a;   // [1, a1..ap]
  double variance = 0.0;   // driving-noise (one-step prediction error) variance
  std::size_t order() const { return a.empty() ? 0 : a.size() - 1; }
};

/// Autocorrelation r(0..max_lag) of the stationary process the model defines:
/// r(0..p) from the Yule-Walker equations, then r(k) = -sum a_i r(k-i).
/// Returns an empty vector if the model is not stationary (singular system or
/// negative r(0)).
std::vector<double> ar_autocorrelation(const ArModel& model, std::size_t max_lag);

/// One-sided PSD [unit^2/Hz] at f_hz for a series sampled at fs_hz:
/// S(f) = 2 * variance / fs / |A(exp(j 2 pi f / fs))|^2.
double ar_psd_one_sided(const ArModel& model, double f_hz, double fs_hz);

/// True if every root of A(z) lies strictly inside the unit circle
/// (checked through the step-down recursion: all |reflection| < 1).
bool ar_is_stable(const ArModel& model);

}  // namespace sinu::noise
