#pragma once
// Mean removal before autocorrelation, GM and AR fitting. The mean of a static
// session is the sensor's turn-on bias; it is reported separately and never
// enters the stochastic models (Allan deviation is computed on the raw series).
#include <span>
#include <vector>

namespace sinu::noise {

/// Arithmetic mean (compensated summation: an 8 h session has ~1e6 samples).
double series_mean(std::span<const double> x);

/// x minus its mean; `turn_on_bias` receives the mean.
std::vector<double> remove_mean(std::span<const double> x, double& turn_on_bias);

}  // namespace sinu::noise
