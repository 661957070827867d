#pragma once
// The carried effects whose assumed value the unit's configuration sets (the
// rest are assumed zero without their states): what diagnose measures a
// carried estimate against, and the option a user corrects it with. One row
// per effect.
#include <Eigen/Core>

#include "estimator/ekf/effects/effect_spec.hpp"
#include "firmware/board/nav_unit_config.hpp"

namespace sinu::diagnose {

struct ConfiguredEffect {
  est::Effect effect;
  const char* option;  // the replay/diagnose option that sets it
  double (*assumed)(const board::NavUnitConfig& unit, Eigen::Index k);
};

inline constexpr ConfiguredEffect kConfiguredEffects[] = {
    {est::Effect::GpsLatency, "--gps-latency", [](const board::NavUnitConfig& u, Eigen::Index) { return u.gps_latency_s; }},
    {est::Effect::LeverArm, "--lever-arm", [](const board::NavUnitConfig& u, Eigen::Index k) { return u.lever_arm_b_m(k); }},
};

/// The row of `effect`, or nullptr when the configuration does not set it.
inline const ConfiguredEffect* configured_effect(est::Effect effect) {
  for (const ConfiguredEffect& c : kConfiguredEffects)
    if (c.effect == effect) return &c;
  return nullptr;
}

/// What the model assumes of component k without the effect's states.
inline double assumed_value(est::Effect effect, Eigen::Index k, const board::NavUnitConfig& unit) {
  const ConfiguredEffect* c = configured_effect(effect);
  return c ? c->assumed(unit, k) : 0.0;
}

}  // namespace sinu::diagnose
