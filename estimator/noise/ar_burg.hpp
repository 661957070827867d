#pragma once
// AR(1..max_order) by Burg's method, as MATLAB's arburg (and Octave's signal
// arburg, whose *output* follows MATLAB although its help text shows the
// opposite sign): each reflection coefficient minimises the sum of forward and
// backward prediction-error powers, k = -2 sum f b / sum (f^2 + b^2); the
// variance starts at x'x/N and is multiplied by (1 - k^2) per order. Burg is
// order-recursive, so one O(N * max_order) pass gives every order, and each
// equals arburg(x, p). |k| <= 1 by construction: the model is always stable.
#include <cstddef>
#include <span>
#include <vector>

#include "estimator/noise/ar_model.hpp"

namespace sinu::noise {

std::vector<ArModel> ar_burg(std::span<const double> x, std::size_t max_order);

}  // namespace sinu::noise
