#include "estimator/noise/allan_deviation.hpp"

#include <cmath>
#include <limits>

#include "estimator/noise/mean_removal.hpp"

namespace sinu::noise {

namespace {

// Wilson-Hilferty: chi-square quantile for edf nu at standard-normal quantile z.
double chi2_quantile(double nu, double z) {
  const double c = 2.0 / (9.0 * nu);
  const double t = 1.0 - c + z * std::sqrt(c);
  return nu * t * t * t;
}

constexpr double kOneSigmaZ = 1.0;  // ~68.3% two-sided interval

}  // namespace

std::vector<AllanPoint> overlapping_allan(std::span<const double> rate, double dt_s, int per_octave) {
  const std::size_t n = rate.size();
  std::vector<AllanPoint> out;
  if (n < 8 || per_octave < 1) return out;
  const double mean = series_mean(rate);
  std::vector<double> theta(n + 1);
  theta[0] = 0.0;
  for (std::size_t i = 0; i < n; ++i) theta[i + 1] = theta[i] + (rate[i] - mean) * dt_s;

  const std::size_t m_max = n / 4;
  std::size_t last_m = 0;
  for (int j = 0;; ++j) {
    const auto m = static_cast<std::size_t>(std::llround(std::pow(2.0, static_cast<double>(j) / per_octave)));
    if (m > m_max) break;
    if (m == last_m) continue;
    last_m = m;
    const double tau = static_cast<double>(m) * dt_s;
    double sum = 0.0;
    const std::size_t terms = n + 1 - 2 * m;
    for (std::size_t k = 0; k < terms; ++k) {
      const double d = theta[k + 2 * m] - 2.0 * theta[k + m] + theta[k];
      sum += d * d;
    }
    const double avar = sum / (2.0 * tau * tau * static_cast<double>(terms));
    AllanPoint p;
    p.tau_s = tau;
    p.cluster = m;
    p.adev = std::sqrt(avar);
    const double nn = static_cast<double>(n + 1);  // phase points
    const double md = static_cast<double>(m);
    double edf = (3.0 * (nn - 1.0) / (2.0 * md) - 2.0 * (nn - 2.0) / nn) * 4.0 * md * md / (4.0 * md * md + 5.0);
    if (edf < 1.0) edf = 1.0;
    p.edf = edf;
    p.adev_low = std::sqrt(avar * edf / chi2_quantile(edf, kOneSigmaZ));
    const double lo_q = chi2_quantile(edf, -kOneSigmaZ);
    p.adev_high = lo_q > 0.0 ? std::sqrt(avar * edf / lo_q) : std::numeric_limits<double>::infinity();
    out.push_back(p);
  }
  return out;
}

}  // namespace sinu::noise
