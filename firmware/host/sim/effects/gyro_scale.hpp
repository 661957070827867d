#pragma once
// gyro_scale [ppm x3]: measured = (1 + s) true, per axis.
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct GyroScale {
  static constexpr const char* name = "gyro_scale";
  static constexpr auto member = &Effects::gyro_scale_ppm;  // where a flight's value lives
  using Value = Eigen::Vector3d;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_vector(v, out, why); }
  static nlohmann::json to_json(const Value& v) { return vector_json(v); }
  static Value draw(Rng& rng) { return signed_vector(rng, 10000.0, 30000.0); }
  static void apply(const Value& v, SensorEffects& s) { s.gyro_scale = v * 1e-6; }
};

}  // namespace sinu::sim::effects
