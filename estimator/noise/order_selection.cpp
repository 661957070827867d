#include "estimator/noise/order_selection.hpp"

#include <cmath>
#include <limits>

namespace sinu::noise {

OrderCriteria order_criteria(double variance, std::size_t order, std::size_t n_samples) {
  const double n = static_cast<double>(n_samples);
  const double p = static_cast<double>(order);
  OrderCriteria c;
  c.fpe = variance * (n + p + 1.0) / (n - p - 1.0);
  c.aic = n * std::log(variance) + 2.0 * p;
  c.bic = n * std::log(variance) + p * std::log(n);
  return c;
}

SelectedOrders select_orders(std::span<const ArModel> models, std::size_t n_samples) {
  SelectedOrders s;
  double best_fpe = std::numeric_limits<double>::infinity(), best_aic = best_fpe, best_bic = best_fpe;
  for (const ArModel& m : models) {
    if (!(m.variance > 0.0)) continue;
    const OrderCriteria c = order_criteria(m.variance, m.order(), n_samples);
    if (c.fpe < best_fpe) best_fpe = c.fpe, s.fpe = m.order();
    if (c.aic < best_aic) best_aic = c.aic, s.aic = m.order();
    if (c.bic < best_bic) best_bic = c.bic, s.bic = m.order();
  }
  return s;
}

}  // namespace sinu::noise
