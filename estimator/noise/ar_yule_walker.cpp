#include "estimator/noise/ar_yule_walker.hpp"

#include "estimator/noise/autocorrelation.hpp"
#include "estimator/noise/levinson.hpp"

namespace sinu::noise {

std::vector<ArModel> ar_yule_walker(std::span<const double> x, std::size_t max_order) {
  if (x.size() <= max_order + 1) return {};
  const std::vector<double> r = autocorrelation_direct(x, max_order, AcfScale::Biased);
  return levinson_durbin(r, max_order);
}

}  // namespace sinu::noise
