#pragma once
// gps_velocity_latency [s, 0..0.5]: the receiver's velocity is this much
// older than its position (a velocity averaged over the epoch interval is
// the interval's middle): the antenna's true velocity tau earlier
// (GpsReceiver keeps the last second of it).
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct GpsVelocityLatency {
  static constexpr const char* name = "gps_velocity_latency";
  static constexpr auto member = &Effects::gps_velocity_latency_s;  // where a flight's value lives
  using Value = double;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_seconds(v, 0.5, out, why); }
  static nlohmann::json to_json(const Value& v) { return v; }
  // Half a 5-Hz period and more: a tenth of a second is 1 m/s^2 x 0.1 m/s against 0.05 m/s of noise
  static Value draw(Rng& rng) { return rng.uniform(0.1, 0.25); }
  static void apply(const Value& v, SensorEffects& s) { s.gps_velocity_latency_s = v; }
};

}  // namespace sinu::sim::effects
