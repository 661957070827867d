#pragma once
// mag_misalign [rad x3]: the magnetometer's axes turned by small angles theta
// against the IMU's (a compass mounted a few degrees off):
//   m = S R m_earth_b (+ hard iron),  R = exp(-[theta x]) the exact rotation.
#include <Eigen/Geometry>

#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/effects.hpp"

namespace sinu::sim::effects {

struct MagMisalign {
  static constexpr const char* name = "mag_misalign";
  static constexpr auto member = &Effects::mag_misalign_rad;  // where a flight's value lives
  using Value = Eigen::Vector3d;
  static bool parse(const nlohmann::json& v, Value& out, std::string& why) { return read_vector(v, out, why); }
  static nlohmann::json to_json(const Value& v) { return vector_json(v); }
  /// 1-3 deg per axis.
  static Value draw(Rng& rng) { return signed_vector(rng, 1.0 * kDegToRad, 3.0 * kDegToRad); }
  static void apply(const Value& v, SensorEffects& s) {
    const double angle = v.norm();
    if (angle > 0.0) s.mag_axes = Eigen::AngleAxisd(-angle, v / angle).toRotationMatrix();
  }
};

}  // namespace sinu::sim::effects
