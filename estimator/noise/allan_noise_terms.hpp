#pragma once
// Noise terms from an Allan deviation curve (IEEE Std 952-1997, annex C):
//   AVAR(tau) = 3 Q^2 / tau^2          quantisation            slope -1
//             + N^2 / tau              angle/velocity random walk  -1/2
//             + (2 ln2 / pi) B^2       bias instability (flicker)   0
//             + K^2 tau / 3            rate random walk           +1/2
//             + R^2 tau^2 / 2          rate ramp                  +1
// Units for a gyro in rad/s: Q rad, N rad/s/sqrt(Hz) = rad/sqrt(s) (equal to
// the white part's ADEV at tau = 1 s), B rad/s, K rad/s/sqrt(s), R rad/s^2;
// for an accelerometer replace rad by m/s.
//
// The five non-negative coefficients are fitted together by weighted
// non-negative least squares on AVAR (exact NNLS by trying every subset of
// the five basis functions): each point's residual is relative (divided by
// the measured AVAR) and weighted by sqrt(edf), so the many well-averaged
// short-tau points do not drown the few long-tau ones, and a term the data do
// not support comes out exactly zero instead of negative.
//
// Bias instability is reported the way IEEE 952 reads it off the plot: the
// floor (first local minimum) of the measured ADEV divided by
// sqrt(2 ln2 / pi) = 0.664 (`B`), with the tau where it occurs. The fitted flicker floor (`B_fit`) is given too;
// the two agree for true flicker noise, and differ when the "instability" is a
// Gauss-Markov bump (then B is the figure datasheets quote).
#include <span>

#include "estimator/noise/allan_deviation.hpp"

namespace sinu::noise {

struct AllanNoiseTerms {
  double Q = 0.0;       // quantisation [unit*s]
  double N = 0.0;       // white-noise density [unit/sqrt(Hz)]
  double B = 0.0;       // bias instability from the ADEV minimum [unit]
  double B_tau_s = 0.0; // tau of that minimum [s]
  double B_fit = 0.0;   // fitted flicker floor [unit]
  double K = 0.0;       // rate random walk [unit/sqrt(s)]
  double R = 0.0;       // rate ramp [unit/s]
  bool floor_reached = false;  // a local minimum exists (else B is an upper bound)
  bool valid = false;

  /// ADEV of the fitted model (the five terms, B_fit as the flat part).
  double model_adev(double tau_s) const;
};

inline constexpr double kFlickerAdevFactor = 0.66428;  // sqrt(2 ln2 / pi)

AllanNoiseTerms fit_allan_noise_terms(std::span<const AllanPoint> curve);

}  // namespace sinu::noise
