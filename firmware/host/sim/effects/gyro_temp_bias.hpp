#pragma once
// gyro_temp_bias [rad/s/degC x3]: bias += k (T - 25 degC).
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct GyroTempBias {
  static constexpr const char* name = "gyro_temp_bias";
  static constexpr auto member = &Effects::gyro_temp_bias_rad_s_per_degC;  // where a flight's value lives
  using Value = Eigen::Vector3d;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_vector(v, out, why); }
  static nlohmann::json to_json(const Value& v) { return vector_json(v); }
  static Value draw(Rng& rng) { return signed_vector(rng, 0.01 * kDegToRad, 0.03 * kDegToRad); }
  static void apply(const Value& v, SensorEffects& s) { s.gyro_temp_per_degC = v; }
};

}  // namespace sinu::sim::effects
