#pragma once
// gyro_g_sensitivity [rad/s per m/s^2, 3x3]: gyro += G f_b (true specific force).
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct GyroGSensitivity {
  static constexpr const char* name = "gyro_g_sensitivity";
  static constexpr auto member = &Effects::gyro_g_sensitivity_rad_s_per_m_s2;  // where a flight's value lives
  using Value = Eigen::Matrix3d;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_matrix(v, out, why); }
  static nlohmann::json to_json(const Value& v) { return matrix_json(v); }
  /// 0.05-0.15 deg/s per g on the diagonal, a third of it across axes.
  static Value draw(Rng& rng) {
    const double lo = 0.05 * kDegToRad / 9.80665, hi = 0.15 * kDegToRad / 9.80665;
    Eigen::Matrix3d g = off_diagonal(rng, lo / 3.0, hi / 3.0);
    for (Eigen::Index i = 0; i < 3; ++i) g(i, i) = rng.signed_uniform(lo, hi);
    return g;
  }
  static void apply(const Value& v, SensorEffects& s) { s.gyro_g_sensitivity = v; }
};

}  // namespace sinu::sim::effects
