#pragma once
// Order-selection criteria for an AR(p) fitted to N samples with driving-noise
// variance v (smaller is better):
//   FPE = v (N + p + 1) / (N - p - 1)      Akaike's final prediction error
//   AIC = N ln v + 2 p                      Akaike information criterion
//   BIC = N ln v + p ln N                   Schwarz / Bayesian (MDL)
// FPE and AIC tend to over-fit long records; BIC is consistent.
#include <cstddef>
#include <span>

#include "estimator/noise/ar_model.hpp"

namespace sinu::noise {

struct OrderCriteria {
  double fpe = 0.0, aic = 0.0, bic = 0.0;
};

OrderCriteria order_criteria(double variance, std::size_t order, std::size_t n_samples);

/// Order (1-based) minimising each criterion over models[0..] (order i+1).
struct SelectedOrders {
  std::size_t fpe = 0, aic = 0, bic = 0;
};
SelectedOrders select_orders(std::span<const ArModel> models, std::size_t n_samples);

}  // namespace sinu::noise
