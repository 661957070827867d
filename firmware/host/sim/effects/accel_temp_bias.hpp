#pragma once
// accel_temp_bias [m/s^2/degC x3]: bias += k (T - 25 degC).
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct AccelTempBias {
  static constexpr const char* name = "accel_temp_bias";
  static constexpr auto member = &Effects::accel_temp_bias_m_s2_per_degC;  // where a flight's value lives
  using Value = Eigen::Vector3d;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_vector(v, out, why); }
  static nlohmann::json to_json(const Value& v) { return vector_json(v); }
  static Value draw(Rng& rng) { return signed_vector(rng, 3e-3, 8e-3); }
  static void apply(const Value& v, SensorEffects& s) { s.accel_temp_per_degC = v; }
};

}  // namespace sinu::sim::effects
