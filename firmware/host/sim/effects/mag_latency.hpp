#pragma once
// mag_latency [s, 0..0.5]: the magnetometer's reading is of the attitude this
// much earlier than its stamp (a compass read over a slow bus or filtered):
// the body field turned back by the true body rate over tau, exp(tau [w x]).
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct MagLatency {
  static constexpr const char* name = "mag_latency";
  static constexpr auto member = &Effects::mag_latency_s;  // where a flight's value lives
  using Value = double;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_seconds(v, 0.5, out, why); }
  static nlohmann::json to_json(const Value& v) { return v; }
  // A compass polled at 10 Hz and filtered: 0.05 s is 1.5 deg in a 30-deg/s turn against ~1 deg of noise
  static Value draw(Rng& rng) { return rng.uniform(0.05, 0.25); }
  static void apply(const Value& v, SensorEffects& s) { s.mag_latency_s = v; }
};

}  // namespace sinu::sim::effects
