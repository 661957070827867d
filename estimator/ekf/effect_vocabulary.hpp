#pragma once
// The effect vocabulary: every physical effect the EKF can carry as states.
// Each is one file in effects/ (its spec: name, components, unit, prior,
// walk, whether `sinu diagnose` tries it, plausible maximum; and what it does:
// the IMU compensation, its columns of the error dynamics, its rows in each
// aiding source), registered in effects/effect_list.hpp. Everything else that
// lists effects (the state layout, the tuning, nav.csv's columns, the
// diagnosis report's units, the default candidates) is derived from the
// tables here; a static_assert keeps them in enum order. The same names are
// the simulator's (firmware/host/sim/effects.hpp; a test checks that every
// effect it can hide has a file here).
//
// Error states are "true - estimated" and feedback adds them to the estimate.
// The IMU is corrected (ErrorStateFilter::compensate) as
//   f = (I - Ma) (1 - sa) (f_raw - ba - ka dT)
//   w = (I - Mg) (1 - sg) (w_raw - bg - kg dT) - G f
// Ma, Mg: misalignment, off-diagonal only (M(i,j): axis i senses axis j; the
// diagonal is the scale's); G: gyro g-sensitivity, full 3x3.
#include <array>
#include <cstdint>
#include <Eigen/Core>

#include "estimator/ekf/effects/effect_list.hpp"

namespace sinu::est {

inline constexpr std::array<EffectSpec, kEffectCount> kEffects = [] {
  std::array<EffectSpec, kEffectCount> a{};
  std::size_t i = 0;
  for_each_effect([&]<class E>() { a[i++] = E::spec; });
  return a;
}();

constexpr bool vocabulary_in_enum_order() {
  for (std::size_t i = 0; i < kEffectCount; ++i)
    if (static_cast<std::size_t>(kEffects[i].effect) != i) return false;
  return true;
}
static_assert(vocabulary_in_enum_order(), "kEffects must list every Effect once, in enum order");

constexpr const EffectSpec& spec(Effect e) { return kEffects[static_cast<std::size_t>(e)]; }

inline constexpr std::array<const char*, kEffectCount> kEffectNames = [] {
  std::array<const char*, kEffectCount> a{};
  for (std::size_t i = 0; i < kEffectCount; ++i) a[i] = kEffects[i].name;
  return a;
}();
inline constexpr std::array<Eigen::Index, kEffectCount> kEffectDims = [] {
  std::array<Eigen::Index, kEffectCount> a{};
  for (std::size_t i = 0; i < kEffectCount; ++i) a[i] = component_count(kEffects[i].components);
  return a;
}();
/// The most components one effect has (a 3x3 matrix).
inline constexpr std::size_t kMaxEffectDim = 9;
static_assert([] {
  for (const Eigen::Index d : kEffectDims)
    if (static_cast<std::size_t>(d) > kMaxEffectDim) return false;
  return true;
}());
inline constexpr Eigen::Index kMaxEffectStates = [] {
  Eigen::Index n = 0;
  for (const Eigen::Index d : kEffectDims) n += d;
  return n;
}();
/// Where each effect's values start in a flat array of all effects' values (enum order).
inline constexpr std::array<Eigen::Index, kEffectCount> kEffectValueOffset = [] {
  std::array<Eigen::Index, kEffectCount> a{};
  Eigen::Index n = 0;
  for (std::size_t i = 0; i < kEffectCount; ++i) {
    a[i] = n;
    n += kEffectDims[i];
  }
  return a;
}();

/// Name of component i of an effect's states ("" for a scalar).
const char* effect_component_name(Effect e, Eigen::Index i);

/// Looks an effect up by its vocabulary name; false if unknown.
bool effect_from_name(const char* name, std::size_t length, Effect& out);

}  // namespace sinu::est
