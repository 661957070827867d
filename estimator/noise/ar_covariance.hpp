#pragma once
// AR(1..max_order) by the covariance method, as MATLAB's arcov: least-squares
// forward prediction over the samples where every regressor exists (no
// windowing, no zero padding):
//   min_a  sum_{n=p}^{N-1} (x(n) + a1 x(n-1) + ... + ap x(n-p))^2
// variance = that minimum / (N - p). Not guaranteed stable.
// Cost: the lagged products of the longest order are summed once (O(N p)),
// and each order's normal matrix is derived from them by removing the few
// edge products outside its range (O(p^2)); then a (p x p) LDLT solve.
#include <cstddef>
#include <span>
#include <vector>

#include "estimator/noise/ar_model.hpp"

namespace sinu::noise {

std::vector<ArModel> ar_covariance(std::span<const double> x, std::size_t max_order);

}  // namespace sinu::noise
