#include "firmware/host/calibration/model_rate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "estimator/noise/ar_burg.hpp"
#include "estimator/noise/ar_covariance.hpp"
#include "estimator/noise/ar_yule_walker.hpp"
#include "estimator/noise/mean_removal.hpp"
#include "estimator/noise/model_allan.hpp"

namespace sinu::calibration {

namespace {

constexpr double kTauFrom_s = 1.0, kTauTo_s = 100.0;  // the span an outage needs
constexpr std::size_t kMinSamples = 500;               // a model rate needs this many decimated samples

/// Means of consecutive blocks of `d` samples, mean removed.
std::vector<double> block_means(std::span<const double> x, std::size_t d) {
  std::vector<double> y;
  y.reserve(x.size() / d);
  for (std::size_t i = 0; i + d <= x.size(); i += d) {
    double s = 0.0;
    for (std::size_t k = 0; k < d; ++k) s += x[i + k];
    y.push_back(s / static_cast<double>(d));
  }
  double mean = 0.0;
  return noise::remove_mean(y, mean);
}

const noise::ArModel* chosen(const std::array<std::vector<noise::ArModel>, kArMethods>& ar, const ModelChoice& m) {
  const auto& list = ar[m.method];
  return list.size() >= m.order ? &list[m.order - 1] : nullptr;
}

/// The measured points in the span, as (tau, adev).
std::vector<noise::AllanPoint> span_points(const std::vector<noise::AllanPoint>& allan) {
  std::vector<noise::AllanPoint> out;
  for (const auto& p : allan)
    if (p.tau_s >= kTauFrom_s && p.tau_s <= kTauTo_s && p.adev > 0.0) out.push_back(p);
  return out;
}

}  // namespace

double ar_model_adev(const noise::ArModel& model, double dt_s, double tau_s, double white_density) {
  const auto m = static_cast<std::size_t>(std::max(1.0, std::round(tau_s / dt_s)));
  const std::vector<double> r = noise::ar_autocorrelation(model, 2 * m);
  if (r.empty()) return std::numeric_limits<double>::infinity();  // not stationary
  const double avar = noise::allan_variance_of_autocovariance(r, m);
  return std::sqrt(std::max(0.0, avar) + white_density * white_density / tau_s);
}

double gm_model_adev(const noise::GaussMarkov1& gm, double tau_s, double white_density) {
  double avar = 0.0;
  if (gm.crossed && gm.tau_s > 0.0) {
    const double x = tau_s / gm.tau_s;
    avar = gm.variance / (x * x) * (2.0 * x - 3.0 + 4.0 * std::exp(-x) - std::exp(-2.0 * x));
  }
  return std::sqrt(std::max(0.0, avar) + white_density * white_density / tau_s);
}

ModelRate choose_model_rate(const std::array<std::vector<double>, 6>& denoised,
                            const std::array<AxisCalibration, 6>& axes, double dt_s, int denoiser_levels) {
  ModelRate out;
  const double fs = 1.0 / dt_s;
  // Candidates: the IMU rate, the approximation's own rate (fs / 2^levels) and
  // half of it, then 1, 0.5 and 0.2 Hz.
  std::vector<std::size_t> decimations = {1};
  if (denoiser_levels > 0) {
    decimations.push_back(std::size_t{1} << denoiser_levels);
    decimations.push_back(std::size_t{2} << denoiser_levels);
  }
  for (const double hz : {1.0, 0.5, 0.2}) decimations.push_back(static_cast<std::size_t>(std::max(1.0, std::round(fs / hz))));
  std::sort(decimations.begin(), decimations.end());
  decimations.erase(std::unique(decimations.begin(), decimations.end()), decimations.end());

  std::array<std::array<std::vector<noise::ArModel>, kArMethods>, 6> best_fits{};
  double best = std::numeric_limits<double>::infinity();
  for (const std::size_t d : decimations) {
    RateScore rs{fs / static_cast<double>(d), d, std::numeric_limits<double>::infinity()};
    std::array<std::array<std::vector<noise::ArModel>, kArMethods>, 6> fits{};
    double sum = 0.0;
    std::size_t n = 0;
    bool usable = true;
    for (std::size_t i = 0; i < 6 && usable; ++i) {
      if (d == 1) {
        fits[i] = axes[i].ar;  // the IMU rate's fits, done already
      } else {
        const std::vector<double> y = block_means(denoised[i], d);
        if (y.size() < kMinSamples) {
          usable = false;
          break;
        }
        fits[i][YuleWalker] = noise::ar_yule_walker(y, kMaxArOrder);
        fits[i][Covariance] = noise::ar_covariance(y, kMaxArOrder);
        fits[i][Burg] = noise::ar_burg(y, kMaxArOrder);
      }
      const noise::ArModel* m = chosen(fits[i], axes[i].model);
      if (!m) {
        usable = false;
        break;
      }
      for (const auto& p : span_points(axes[i].allan)) {
        const double model = ar_model_adev(*m, dt_s * static_cast<double>(d), p.tau_s, axes[i].terms.N);
        const double e = std::log(model / p.adev);
        sum += e * e;
        ++n;
      }
    }
    if (usable && n > 0) rs.score = std::sqrt(sum / static_cast<double>(n));
    out.candidates.push_back(rs);
    if (rs.score < best) {
      best = rs.score;
      out.rate_hz = rs.rate_hz;
      out.decimation = d;
      best_fits = fits;
    }
  }
  if (!out.valid()) return out;
  for (std::size_t i = 0; i < 6; ++i) {
    AxisAtRate& a = out.axes[i];
    a.ar = best_fits[i];
    const noise::ArModel* at_rate = chosen(a.ar, axes[i].model);
    const noise::ArModel* at_imu = chosen(axes[i].ar, axes[i].model);
    for (const auto& p : span_points(axes[i].allan)) {
      a.tau_s.push_back(p.tau_s);
      a.adev_measured.push_back(p.adev);
      a.adev_gm.push_back(gm_model_adev(axes[i].gm, p.tau_s, axes[i].terms.N));
      a.adev_ar_imu.push_back(at_imu ? ar_model_adev(*at_imu, dt_s, p.tau_s, axes[i].terms.N) : NAN);
      a.adev_ar_model.push_back(at_rate ? ar_model_adev(*at_rate, dt_s * static_cast<double>(out.decimation), p.tau_s,
                                                        axes[i].terms.N)
                                        : NAN);
    }
  }
  return out;
}

}  // namespace sinu::calibration
