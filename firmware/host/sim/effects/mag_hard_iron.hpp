#pragma once
// mag_hard_iron [uT x3]: m += b.
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct MagHardIron {
  static constexpr const char* name = "mag_hard_iron";
  static constexpr auto member = &Effects::mag_hard_iron_uT;  // where a flight's value lives
  using Value = Eigen::Vector3d;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_vector(v, out, why); }
  static nlohmann::json to_json(const Value& v) { return vector_json(v); }
  static Value draw(Rng& rng) { return signed_vector(rng, 10.0, 30.0); }
  static void apply(const Value& v, SensorEffects& s) { s.mag_hard_iron_uT = v; }
};

}  // namespace sinu::sim::effects
