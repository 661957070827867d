#pragma once
// Levinson-Durbin recursion: from autocorrelation r(0..max_order) to the AR
// models of every order 1..max_order in O(max_order^2).
#include <cstddef>
#include <span>
#include <vector>

#include "estimator/noise/ar_model.hpp"

namespace sinu::noise {

/// Step-up recursion: the order-(p) polynomial [1, a1..a_{p-1}] and the
/// reflection coefficient k give [1, a1 + k a_{p-1}, ..., a_{p-1} + k a1, k].
std::vector<double> step_up(const std::vector<double>& a, double k);

/// models[p-1] is the order-p model; its variance is the prediction-error
/// power r(0) * prod (1 - k_i^2). Stops early (shorter result) if r(0) <= 0.
std::vector<ArModel> levinson_durbin(std::span<const double> r, std::size_t max_order);

}  // namespace sinu::noise
