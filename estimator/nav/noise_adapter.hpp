#pragma once
// Measurement noise learnt from the innovations (covariance matching,
// Mehra 1972): for a consistent filter E[y_i^2] = (H P H^T)_ii + R_ii, so
//   r = mean_i (y_i^2 - (H P H^T)_ii)
// is an unbiased sample of the noise variance. Its mean (a running mean at
// first, then exponential over `time_constant_s` of updates), kept within
// [min_sigma, max_sigma], is the R the next update uses; the configured sigma
// counts as `prior_samples` samples. For sources whose noise no message
// states: NMEA has no velocity accuracy, a magnetometer's noise depends on the
// installation. Rejected updates teach it too, each squared innovation
// clipped at clip_sigmas^2 S (a Huber-like bound): learning from the accepted
// ones alone shrinks R while a disturbance (motor currents at a magnetometer)
// is rejected, until nothing is accepted; counted this way a disturbed sensor
// is trusted less, and a single outlier moves R by little.
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
    double sample = 0.0;
    for (Eigen::Index i = 0; i < r.rows; ++i) {
      const double s2 = r.innovation_sigma(i) * r.innovation_sigma(i);
      const double y2 = std::min(r.innovation(i) * r.innovation(i), cfg_.clip_sigmas * cfg_.clip_sigmas * s2);
      sample += y2 - (s2 - variance_);
    }
    sample /= static_cast<double>(r.rows);
    samples_ += 1.0;
    const double a = std::min(1.0, std::max(1.0 / samples_, std::max(dt_s, 0.0) / cfg_.time_constant_s));
    variance_ += a * (sample - variance_);
    variance_ = std::clamp(variance_, cfg_.min_sigma * cfg_.min_sigma, cfg_.max_sigma * cfg_.max_sigma);
  }

 private:
  NoiseAdapterConfig cfg_;
  double variance_ = 0.0;
  double samples_ = 0.0;
};

}  // namespace sinu::est
