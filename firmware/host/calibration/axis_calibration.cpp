#include "firmware/host/calibration/axis_calibration.hpp"

#include <cmath>

#include "estimator/noise/ar_burg.hpp"
#include "estimator/noise/ar_covariance.hpp"
#include "estimator/noise/ar_yule_walker.hpp"
#include "estimator/noise/autocorrelation.hpp"
#include "estimator/noise/mean_removal.hpp"

namespace sinu::calibration {

namespace {

double std_dev(std::span<const double> centred) {
  double s = 0.0;
  for (double v : centred) s += v * v;
  return centred.empty() ? 0.0 : std::sqrt(s / static_cast<double>(centred.size()));
}

}  // namespace

AxisCalibration calibrate_axis(const std::string& axis, std::span<const double> raw,
                               std::span<const double> denoised, const AxisOptions& options) {
  AxisCalibration c;
  c.axis = axis;
  c.samples = raw.size();
  c.model = options.model;
  double bias_raw = 0.0, bias_denoised = 0.0;
  c.raw_std = std_dev(noise::remove_mean(raw, bias_raw));
  c.turn_on_bias = bias_raw;
  const std::vector<double> x = noise::remove_mean(denoised, bias_denoised);
  c.denoised_std = std_dev(x);

  const auto max_lag = static_cast<std::size_t>(options.acf_max_lag_s / options.dt_s);
  c.acf = noise::autocorrelation(x, max_lag, noise::AcfScale::Biased);
  c.gm = noise::fit_gauss_markov1(c.acf, options.dt_s);
  // GM1 as a one-step predictor on the same data, comparable to AR variances.
  const double phi = c.gm.phi(options.dt_s);
  double e2 = 0.0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double e = x[i] - phi * x[i - 1];
    e2 += e * e;
  }
  c.gm_prediction_variance = x.size() > 1 ? e2 / static_cast<double>(x.size() - 1) : 0.0;

  c.ar[YuleWalker] = noise::ar_yule_walker(x, kMaxArOrder);
  c.ar[Covariance] = noise::ar_covariance(x, kMaxArOrder);
  c.ar[Burg] = noise::ar_burg(x, kMaxArOrder);
  for (std::size_t m = 0; m < kArMethods; ++m) c.selected[m] = noise::select_orders(c.ar[m], x.size());

  c.allan = noise::overlapping_allan(raw, options.dt_s, 4);
  c.terms = noise::fit_allan_noise_terms(c.allan);
  return c;
}

}  // namespace sinu::calibration
