#pragma once
// Initial uncertainty and random-walk process noise of the optional effect
// states (defaults from the vocabulary), and the receiver-bias GM process.
#include <array>

#include "estimator/ekf/state_layout.hpp"

namespace sinu::est {

/// A known starting value of an effect (from a model file: what `sinu
/// diagnose --apply` found on an earlier flight), per component.
struct EffectPrior {
  bool given = false;
  std::array<double, kMaxEffectDim> value{}, sigma{};
};

struct EffectTuning {
  // per effect: initial sigma [state unit] and random-walk density [unit/sqrt(s)],
  // the vocabulary's (effect_vocabulary.hpp) unless a caller changes them.
  std::array<double, kEffectCount> initial_sigma = [] {
    std::array<double, kEffectCount> a{};
    for (std::size_t i = 0; i < kEffectCount; ++i) a[i] = kEffects[i].initial_sigma;
    return a;
  }();
  std::array<double, kEffectCount> random_walk = [] {
    std::array<double, kEffectCount> a{};
    for (std::size_t i = 0; i < kEffectCount; ++i) a[i] = kEffects[i].random_walk;
    return a;
  }();
  // gps_position_bias: the receiver's correlated error. Most of a receiver's
  // stated error (GST, or HDOP x UERE) is slow (atmosphere, multipath, orbits:
  // minutes), the rest white: the fix's variance is split, this fraction into
  // the GM states, whatever the receiver (metres standalone, centimetres RTK).
  double gps_bias_variance_fraction = 0.9;
  double gps_bias_tau_s = 120.0;
  // Starting values that replace the zero (or configured) value and the prior sigma.
  std::array<EffectPrior, kEffectCount> prior{};
  double sigma(Effect e) const { return initial_sigma[static_cast<std::size_t>(e)]; }
  double walk(Effect e) const { return random_walk[static_cast<std::size_t>(e)]; }
};

}  // namespace sinu::est
