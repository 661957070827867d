#pragma once
// AR(1..max_order) by Yule-Walker, as MATLAB's aryule and Octave's signal
// aryule: the biased autocorrelation of x as given (no mean removal here),
// solved by Levinson-Durbin. Always stable; biased towards lower resolution
// on short records (the window of the biased estimator).
#include <cstddef>
#include <span>
#include <vector>

#include "estimator/noise/ar_model.hpp"

namespace sinu::noise {

std::vector<ArModel> ar_yule_walker(std::span<const double> x, std::size_t max_order);

}  // namespace sinu::noise
