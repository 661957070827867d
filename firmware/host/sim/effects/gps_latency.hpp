#pragma once
// gps_latency [s, 0..1]: each fix is this much older than its time stamp
// (on top of the receiver's base latency).
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct GpsLatency {
  static constexpr const char* name = "gps_latency";
  static constexpr auto member = &Effects::gps_latency_s;  // where a flight's value lives
  using Value = double;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_seconds(v, 1.0, out, why); }
  static nlohmann::json to_json(const Value& v) { return v; }
  static Value draw(Rng& rng) { return rng.uniform(0.1, 0.3); }
  static void apply(const Value& v, SensorEffects& s) { s.gps_latency_s = v; }
};

}  // namespace sinu::sim::effects
