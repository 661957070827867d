#pragma once
// Section 3 of the paper for one sensor axis: mean (turn-on bias) removed,
// denoised series -> autocorrelation, GM1, AR(1..10) by the three methods,
// order criteria; raw series -> overlapping Allan deviation and noise terms.
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "estimator/noise/allan_deviation.hpp"
#include "estimator/noise/allan_noise_terms.hpp"
#include "estimator/noise/ar_model.hpp"
#include "estimator/noise/gauss_markov.hpp"
#include "estimator/noise/order_selection.hpp"

namespace sinu::calibration {

inline constexpr std::size_t kMaxArOrder = 10;
enum ArMethod : std::size_t { YuleWalker, Covariance, Burg, kArMethods };
inline constexpr std::array<const char*, kArMethods> kArMethodNames = {"yule_walker", "covariance", "burg"};

/// The model the EKF uses (paper: Burg AR(3)).
struct ModelChoice {
  ArMethod method = Burg;
  std::size_t order = 3;
};

struct AxisCalibration {
  std::string axis;
  double turn_on_bias = 0.0;   // mean of the raw series
  double raw_std = 0.0;        // of the raw series
  double denoised_std = 0.0;   // of the mean-removed denoised series
  std::vector<double> acf;     // biased, denoised, lags 0..L
  noise::GaussMarkov1 gm;
  double gm_prediction_variance = 0.0;  // one-step GM1 prediction error variance on the data
  std::array<std::vector<noise::ArModel>, kArMethods> ar;  // [method][p-1]
  std::array<noise::SelectedOrders, kArMethods> selected;
  std::vector<noise::AllanPoint> allan;
  noise::AllanNoiseTerms terms;
  ModelChoice model;
  std::size_t samples = 0;
};

struct AxisOptions {
  double dt_s = 0.025;
  double acf_max_lag_s = 600.0;
  ModelChoice model;
};

/// `raw` is the series as measured, `denoised` the denoiser's output (same length).
AxisCalibration calibrate_axis(const std::string& axis, std::span<const double> raw,
                               std::span<const double> denoised, const AxisOptions& options);

}  // namespace sinu::calibration
