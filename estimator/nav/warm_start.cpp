#include "estimator/nav/warm_start.hpp"

#include <algorithm>
#include <cmath>

namespace sinu::est {

bool checked_by_the_field(Effect e) {
  return e == Effect::MagHardIron || e == Effect::MagSoftIron || e == Effect::MagMotorInterference;
}

bool checked_by_the_rest(Effect e) { return e == Effect::AccelBias || e == Effect::GyroBias; }

WarmStart aged(const WarmStart& w, double age_s, const EffectTuning& tuning) {
  WarmStart out = w;
  const double age = std::max(0.0, age_s);
  for (std::size_t e = 0; e < kEffectCount; ++e) {
    EffectPrior& p = out.effects[e];
    if (!p.given) continue;
    const auto n = static_cast<std::size_t>(kEffectDims[e]);
    if (static_cast<Effect>(e) == Effect::GpsPositionBias) {
      const double decay = std::exp(-age / tuning.gps_bias_tau_s);
      for (std::size_t k = 0; k < n; ++k) {
        const double level = w.gps_bias_level_ned_m(static_cast<Eigen::Index>(k));
        p.value[k] *= decay;
        p.sigma[k] = std::sqrt(p.sigma[k] * p.sigma[k] * decay * decay + level * level * (1.0 - decay * decay));
      }
      continue;
    }
    const double walk = tuning.random_walk[e];
    for (std::size_t k = 0; k < n; ++k) p.sigma[k] = std::sqrt(p.sigma[k] * p.sigma[k] + walk * walk * age);
  }
  return out;
}

void keep_tighter(EffectPrior& saved, std::size_t k, double cold_value, double cold_sigma) {
  if (saved.sigma[k] < cold_sigma) return;
  saved.value[k] = cold_value;
  saved.sigma[k] = cold_sigma;
}

}  // namespace sinu::est
