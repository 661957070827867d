#pragma once
// Measurement noise learnt from the innovations (covariance matching,
// Mehra 1972): for a consistent filter E[y_i^2] = (H P H^T)_ii + R_ii, so
//   r = mean_i (y_i^2 - (H P H^T)_ii)
// is an unbiased sample of the noise variance, but a noisy one: its variance
// is 2 S_ii^2 (S = H P H^T + R), so while the state is uncertain (S >> R, the
// first updates after alignment) one sample says nothing about R and, taken at
// full weight, a small innovation against a large S made R negative and the
// learnt sigma fell to its floor on the first update. Each row is weighted by
// its information on R relative to a row with H P H^T = 0, (R / S_ii)^2. The
// weighted mean (a running mean at first, then exponential over
// `time_constant_s`), kept within
// [min_sigma, max_sigma], is the R the next update uses; the configured sigma
// counts as `prior_samples` samples. For sources whose noise no message
// states: NMEA has no velocity accuracy, a magnetometer's noise depends on the
// installation. Rejected updates teach it too, each squared innovation
// clipped at clip_sigmas^2 S (a Huber-like bound): learning from the accepted
// ones alone shrinks R while a disturbance (motor currents at a magnetometer)
// is rejected, until nothing is accepted; counted this way a disturbed sensor
// is trusted less, and a single outlier moves R by little.
//
// learn_scale() learns a factor k on a sigma that varies from update to
// update (a GNSS position sigma guessed as DOP x UERE): rows first..first+
// count-1 are divided by their noise sigma over k (the guess), so sigma() is
// k and the update after uses k times the next guess.
#include <algorithm>
#include <cmath>

#include "estimator/ekf/measurement_update.hpp"

namespace sinu::est {

struct NoiseAdapterConfig {
  bool enabled = true;
  double time_constant_s = 60.0;
  double min_sigma = 0.0, max_sigma = 1e9;
  double prior_samples = 20.0;
  double clip_sigmas = 5.0;
};

class NoiseAdapter {
 public:
  void configure(const NoiseAdapterConfig& cfg, double initial_sigma) {
    cfg_ = cfg;
    variance_ = initial_sigma * initial_sigma;
    samples_ = cfg.prior_samples;
  }
  double sigma() const { return std::sqrt(variance_); }
  /// One update (accepted or not) made with noise sigma(), dt_s after the last.
  void learn(const UpdateResult& r, double dt_s) {
    if (!cfg_.enabled || r.rows == 0 || !r.innovation.head(r.rows).allFinite()) return;
    double sum = 0.0, weight = 0.0;
    for (Eigen::Index i = 0; i < r.rows; ++i) {
      const double s2 = r.innovation_sigma(i) * r.innovation_sigma(i);
      if (!(s2 > 0.0)) continue;
      const double y2 = std::min(r.innovation(i) * r.innovation(i), cfg_.clip_sigmas * cfg_.clip_sigmas * s2);
      const double w = std::min(1.0, (variance_ / s2) * (variance_ / s2));
      sum += w * (y2 - (s2 - variance_));
      weight += w;
    }
    if (!(weight > 0.0)) return;
    const double sample = sum / weight;
    weight /= static_cast<double>(r.rows);  // in full samples
    // Its share: its weight over the total, which forgets over the time
    // constant (a running mean while the total grows, then exponential; a
    // steady weight keeps the time constant whatever its size).
    samples_ = samples_ * std::exp(-std::max(dt_s, 0.0) / cfg_.time_constant_s) + weight;
    variance_ += std::min(1.0, weight / samples_) * (sample - variance_);
    variance_ = std::clamp(variance_, cfg_.min_sigma * cfg_.min_sigma, cfg_.max_sigma * cfg_.max_sigma);
  }
  /// One update made with noise k x guess on rows first..first+count-1 (k = sigma()).
  void learn_scale(const UpdateResult& r, Eigen::Index first, Eigen::Index count, double dt_s) {
    UpdateResult n;
    for (Eigen::Index i = 0; i < count && first + i < r.rows; ++i) {
      const double guess = r.noise_sigma(first + i) / sigma();
      if (!(guess > 0.0)) return;
      n.innovation(i) = r.innovation(first + i) / guess;
      n.innovation_sigma(i) = r.innovation_sigma(first + i) / guess;
      n.rows = i + 1;
    }
    learn(n, dt_s);
  }

 private:
  NoiseAdapterConfig cfg_;
  double variance_ = 0.0;
  double samples_ = 0.0;
};

}  // namespace sinu::est
