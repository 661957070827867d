#pragma once
// The Allan variance a noise model predicts, from its autocovariance: what a
// bench measures (allan_deviation.hpp) against what a GM1 or an AR(p) model
// at some rate says, over the averaging times an outage spans.
// For a stationary series with autocovariance R(k) sampled every dt, the
// averages y_bar over m samples (tau = m dt) have
//   Var(y_bar)              = (1/m^2) [m R(0) + 2 sum_{k=1}^{m-1} (m - k) R(k)]
//   Cov(y_bar_n, y_bar_n+1) = (1/m^2) sum_{k=-(m-1)}^{m-1} (m - |k|) R(m + k)
//   AVAR(tau) = (1/2) E[(y_bar_n+1 - y_bar_n)^2] = Var(y_bar) - Cov(...),
// which needs R up to lag 2m - 1. White noise of density N adds N^2 / tau.
#include <cstddef>
#include <span>

namespace sinu::noise {

/// AVAR at tau = m * dt from the autocovariance r(0..) (r.size() >= 2m); NaN if too short.
double allan_variance_of_autocovariance(std::span<const double> r, std::size_t m);

}  // namespace sinu::noise
