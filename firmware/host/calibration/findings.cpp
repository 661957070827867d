// Plain-language statements of where GM1, AR and the Allan noise model fail to
// describe the measured series. Thresholds are stated where they are used.
#include <fmt/format.h>

#include <cmath>

#include "estimator/noise/ar_model.hpp"
#include "firmware/host/calibration/calibration_run.hpp"

namespace sinu::calibration {

namespace {

// A normalised autocorrelation below this is a real negative lobe: the
// standard error of rho(k) for these long series is ~0.01-0.03.
constexpr double kNegativeLobe = -0.1;
// Model and measured normalised autocorrelation differing by more than this
// is a visible misfit on the report plot.
constexpr double kAcfMisfit = 0.2;
// Window over which the autocorrelation misfit is judged [s].
constexpr double kAcfWindow_s = 120.0;

struct Lobe {
  bool found = false;
  double min_rho = 0.0, min_lag_s = 0.0, period_s = 0.0;
};

Lobe negative_lobe(const std::vector<double>& acf, double dt) {
  Lobe l;
  if (acf.size() < 3 || !(acf[0] > 0.0)) return l;
  std::size_t k_min = 0;
  double rho_min = 0.0;
  for (std::size_t k = 1; k < acf.size(); ++k) {
    const double rho = acf[k] / acf[0];
    if (rho < rho_min) rho_min = rho, k_min = k;
    if (k_min != 0 && rho > rho_min + 0.05) break;  // past the first trough
  }
  if (rho_min > kNegativeLobe) return l;
  l.found = true;
  l.min_rho = rho_min;
  l.min_lag_s = static_cast<double>(k_min) * dt;
  l.period_s = 2.0 * l.min_lag_s;  // half a period to the first trough
  for (std::size_t k = k_min + 1; k + 1 < acf.size(); ++k) {  // the next crest, if any
    if (acf[k] >= acf[k - 1] && acf[k] > acf[k + 1] && acf[k] > 0.05 * acf[0]) {
      l.period_s = static_cast<double>(k) * dt;
      break;
    }
  }
  return l;
}

}  // namespace

std::vector<std::string> findings(const AxisCalibration& a, double dt) {
  std::vector<std::string> out;
  const std::string& ax = a.axis;
  if (a.acf.empty() || !(a.acf[0] > 0.0)) {
    out.push_back(fmt::format("{}: the series is constant; no stochastic model can be fitted.", ax));
    return out;
  }
  const Lobe lobe = negative_lobe(a.acf, dt);
  if (lobe.found) {
    out.push_back(fmt::format(
        "{}: GM1 misses the periodic component near {:.3g} s: the measured autocorrelation swings to {:.2f} of "
        "r(0) at {:.3g} s, which an exponential never does.",
        ax, lobe.period_s, lobe.min_rho, lobe.min_lag_s));
  }
  if (!a.gm.crossed) {
    out.push_back(fmt::format(
        "{}: the autocorrelation does not fall to 1/e within {:.0f} s: at these time scales the error behaves like a "
        "random walk or drift, which GM1 (and any stationary AR model) cannot represent.",
        ax, static_cast<double>(a.acf.size() - 1) * dt));
  }
  // Misfit of GM1 and of the chosen AR model over the first kAcfWindow_s.
  const auto& chosen = a.ar[a.model.method];
  const std::size_t window = std::min(a.acf.size(), static_cast<std::size_t>(kAcfWindow_s / dt) + 1);
  std::vector<double> ar_acf;
  if (chosen.size() >= a.model.order) ar_acf = noise::ar_autocorrelation(chosen[a.model.order - 1], window - 1);
  double gm_worst = 0.0, gm_worst_lag = 0.0, ar_worst = 0.0, ar_worst_lag = 0.0;
  for (std::size_t k = 0; k < window; ++k) {
    const double rho = a.acf[k] / a.acf[0];
    const double lag = static_cast<double>(k) * dt;
    const double gm = a.gm.autocorrelation(lag) / a.gm.variance;
    if (std::abs(rho - gm) > gm_worst) gm_worst = std::abs(rho - gm), gm_worst_lag = lag;
    if (!ar_acf.empty()) {
      const double ar = ar_acf[k] / ar_acf[0];
      if (std::abs(rho - ar) > ar_worst) ar_worst = std::abs(rho - ar), ar_worst_lag = lag;
    }
  }
  const std::string model_name = fmt::format("{} AR({})", kArMethodNames[a.model.method], a.model.order);
  if (gm_worst > kAcfMisfit && !lobe.found) {
    out.push_back(fmt::format("{}: GM1 departs from the measured autocorrelation by {:.2f} of r(0) at {:.3g} s.", ax,
                              gm_worst, gm_worst_lag));
  }
  if (ar_acf.empty()) {
    out.push_back(fmt::format("{}: {} is not stationary; it has no autocorrelation to compare.", ax, model_name));
  } else if (ar_worst > kAcfMisfit) {
    out.push_back(fmt::format(
        "{}: {} departs from the measured autocorrelation by {:.2f} of r(0) at {:.3g} s: its poles describe the "
        "first lags (the denoising filter) and not the slow error.",
        ax, model_name, ar_worst, ar_worst_lag));
  }
  // Allan deviation: slope at the long end and terms the EKF models lack.
  if (a.allan.size() >= 4 && a.terms.valid) {
    const auto& p1 = a.allan[a.allan.size() - 4];
    const auto& p2 = a.allan.back();
    const double slope = std::log(p2.adev / p1.adev) / std::log(p2.tau_s / p1.tau_s);
    const double t = p2.tau_s;
    const double rrw = a.terms.K * std::sqrt(t / 3.0), ramp = a.terms.R * t / std::sqrt(2.0);
    const double white = a.terms.N / std::sqrt(t);
    if ((rrw > white || ramp > white) && slope > 0.2) {
      out.push_back(fmt::format(
          "{}: Allan deviation rises beyond {:.3g} s (slope {:+.2f}): {} is present (K = {:.3g}, R = {:.3g}); GM1 and "
          "AR are stationary and do not contain it: add a random-walk bias state.",
          ax, a.terms.B_tau_s, slope, ramp > rrw ? "rate ramp" : "rate random walk", a.terms.K, a.terms.R));
    }
    if (!a.terms.floor_reached) {
      out.push_back(fmt::format(
          "{}: Allan deviation is still falling at {:.3g} s: the bias-instability floor was not reached, B = {:.3g} "
          "is an upper bound (record longer).",
          ax, t, a.terms.B));
    }
    // Where the five-term model leaves the measured curve's interval by far.
    for (const auto& p : a.allan) {
      const double m = a.terms.model_adev(p.tau_s);
      const double half_width = 0.5 * (p.adev_high - p.adev_low);
      if (p.edf > 30.0 && std::abs(m - p.adev) > 3.0 * half_width && std::abs(m - p.adev) > 0.15 * p.adev) {
        out.push_back(fmt::format(
            "{}: the white/flicker/random-walk noise model misses the measured Allan deviation near {:.3g} s "
            "({:.3g} measured, {:.3g} modelled): a correlated (Gauss-Markov or periodic) component is present.",
            ax, p.tau_s, p.adev, m));
        break;
      }
    }
  }
  return out;
}

}  // namespace sinu::calibration
