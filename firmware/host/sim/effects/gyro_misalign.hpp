#pragma once
// gyro_misalign [rad, 3x3]: measured = (I + M) true, M off-diagonal.
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct GyroMisalign {
  static constexpr const char* name = "gyro_misalign";
  static constexpr auto member = &Effects::gyro_misalign_rad;  // where a flight's value lives
  using Value = Eigen::Matrix3d;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_misalignment(v, out, why); }
  static nlohmann::json to_json(const Value& v) { return matrix_json(v); }
  static Value draw(Rng& rng) { return off_diagonal(rng, 5.0 * kMrad, 15.0 * kMrad); }
  static void apply(const Value& v, SensorEffects& s) { s.gyro_misalign = v; }
};

}  // namespace sinu::sim::effects
