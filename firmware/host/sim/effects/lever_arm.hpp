#pragma once
// lever_arm [m x3, body FRD]: the GPS antenna = IMU + C_nb l (position and velocity).
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct LeverArm {
  static constexpr const char* name = "lever_arm";
  static constexpr auto member = &Effects::lever_arm_b_m;  // where a flight's value lives
  using Value = Eigen::Vector3d;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_vector(v, out, why); }
  static nlohmann::json to_json(const Value& v) { return vector_json(v); }
  static Value draw(Rng& rng) { return signed_vector(rng, 0.4, 1.0); }
  static void apply(const Value& v, SensorEffects& s) { s.lever_arm_b_m = v; }
};

}  // namespace sinu::sim::effects
