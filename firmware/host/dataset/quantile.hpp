#pragma once
// The q-quantile of a series (0 for none): the element at floor(q (n - 1)) of
// the sorted values. Host-side statistics (plots, bench checks), not the hot path.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace sinu::dataset {

inline double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

}  // namespace sinu::dataset
