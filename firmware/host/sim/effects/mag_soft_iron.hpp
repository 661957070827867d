#pragma once
// mag_soft_iron [3x3]: m = S m_earth_b (+ hard iron); nominal S = I.
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct MagSoftIron {
  static constexpr const char* name = "mag_soft_iron";
  static constexpr auto member = &Effects::mag_soft_iron;  // where a flight's value lives
  using Value = Eigen::Matrix3d;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_matrix(v, out, why); }
  static nlohmann::json to_json(const Value& v) { return matrix_json(v); }
  /// Symmetric: 3-8 % across axes, 5-15 % per axis.
  static Value draw(Rng& rng) {
    const Eigen::Matrix3d p = off_diagonal(rng, 0.03, 0.08);
    Eigen::Matrix3d s = Eigen::Matrix3d::Identity() + 0.5 * (p + p.transpose());
    for (Eigen::Index i = 0; i < 3; ++i) s(i, i) += rng.signed_uniform(0.05, 0.15);
    return s;
  }
  static void apply(const Value& v, SensorEffects& s) { s.mag_soft_iron = v; }
};

}  // namespace sinu::sim::effects
