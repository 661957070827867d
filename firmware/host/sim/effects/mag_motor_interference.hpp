#pragma once
// mag_motor_interference [uT per m/s^2 x3]: m += k (-f_z - g0), f_z the true
// body-z specific force: the field of the motors' current, which follows the
// thrust (a hover's -f_z is g0; a climb, a pull-up or a banked turn raise it).
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct MagMotorInterference {
  static constexpr const char* name = "mag_motor_interference";
  static constexpr auto member = &Effects::mag_motor_uT_per_m_s2;  // where a flight's value lives
  using Value = Eigen::Vector3d;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_vector(v, out, why); }
  static nlohmann::json to_json(const Value& v) { return vector_json(v); }
  /// 0.5-2 uT per m/s^2 per axis: 2-8 uT through a 30-45 deg banked turn, an
  /// internal compass next to the power wiring.
  static Value draw(Rng& rng) { return signed_vector(rng, 0.5, 2.0); }
  static void apply(const Value& v, SensorEffects& s) { s.mag_motor_uT_per_m_s2 = v; }
};

}  // namespace sinu::sim::effects
