#include "estimator/noise/gauss_markov.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace sinu::noise {

double GaussMarkov1::autocorrelation(double lag_s) const {
  if (!crossed) return variance;
  return variance * std::exp(-std::abs(lag_s) / tau_s);
}

double GaussMarkov1::phi(double dt_s) const { return crossed ? std::exp(-dt_s / tau_s) : 1.0; }

double GaussMarkov1::driving_variance(double dt_s) const {
  const double ph = phi(dt_s);
  return variance * (1.0 - ph * ph);
}

GaussMarkov1 fit_gauss_markov1(std::span<const double> acf, double dt_s) {
  GaussMarkov1 gm;
  if (acf.empty() || !(acf[0] > 0.0)) return gm;
  gm.variance = acf[0];
  const double level = acf[0] / std::numbers::e;
  for (std::size_t k = 1; k < acf.size(); ++k) {
    if (acf[k] <= level) {
      const double frac = (acf[k - 1] - level) / (acf[k - 1] - acf[k]);
      gm.tau_s = (static_cast<double>(k - 1) + frac) * dt_s;
      gm.crossed = true;
      return gm;
    }
  }
  gm.tau_s = std::numeric_limits<double>::infinity();
  return gm;
}

}  // namespace sinu::noise
