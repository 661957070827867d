#pragma once
// First-order Gauss-Markov fit: R(tau) = variance * exp(-|tau| / tau_s).
//
// Method: variance = r(0) of the mean-removed series, and tau_s = the lag at
// which the normalised biased autocorrelation first falls to 1/e (linear
// interpolation between lags). Why this and not the other usual estimators:
//  - the AR(1) route, tau = -dt / ln(r(1)/r(0)), reads only lag 1, which after
//    wavelet denoising (a ~2.5 Hz low-pass at 40 Hz) measures the filter, not
//    the sensor: r(1)/r(0) is ~0.99 for any slow process;
//  - a least-squares exponential fit over many lags is pulled by the long-lag
//    tail, whose estimation variance is large and which for MEMS data is often
//    not exponential at all (periodic-random behaviour, paper Fig. 5-6);
//  - the 1/e crossing is the definition of the correlation time (paper Fig. 4)
//    and is what a bench engineer reads off the plot, so the report can be
//    checked by eye.
// If the autocorrelation never reaches 1/e within the lags given, tau_s is
// +infinity and `crossed` is false (the process looks like a random walk at
// that scale: GM1 is the wrong model and the report says so).
#include <span>

namespace sinu::noise {

struct GaussMarkov1 {
  double tau_s = 0.0;     // correlation time [s]
  double variance = 0.0;  // process variance sigma^2 [unit^2]
  bool crossed = false;   // the 1/e level was reached

  /// Model autocorrelation at lag tau_s_lag [s].
  double autocorrelation(double lag_s) const;
  /// Discrete transition exp(-dt/tau) and driving-noise variance
  /// variance * (1 - exp(-2 dt / tau)) for sample interval dt [s].
  double phi(double dt_s) const;
  double driving_variance(double dt_s) const;
};

/// `acf` is the biased autocorrelation r(0..L) of the mean-removed series,
/// sampled every dt_s seconds.
GaussMarkov1 fit_gauss_markov1(std::span<const double> acf, double dt_s);

}  // namespace sinu::noise
