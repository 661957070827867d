#pragma once
// What the simulator's effect files (sim/effects/*.hpp) share: reading and
// writing their JSON values (a vector of 3, a 3x3 of rows, a number) with a
// reason on failure, drawing magnitudes, and the sensor-model terms the
// effects set (SensorEffects), which ImuSensor and GpsReceiver apply.
#include <Eigen/Core>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <string>

#include "firmware/host/sim/rng.hpp"

namespace sinu::sim::effects {

/// Everything the sensor models do differently because of the effects (nominal: none).
struct SensorEffects {
  Eigen::Vector3d accel_scale = Eigen::Vector3d::Zero(), gyro_scale = Eigen::Vector3d::Zero();  // measured = (1 + s) ...
  Eigen::Matrix3d accel_misalign = Eigen::Matrix3d::Zero(), gyro_misalign = Eigen::Matrix3d::Zero();  // ... (I + M) true
  Eigen::Matrix3d gyro_g_sensitivity = Eigen::Matrix3d::Zero();  // gyro += G f_b
  Eigen::Matrix3d mag_soft_iron = Eigen::Matrix3d::Identity();   // m = S R m_earth_b + h
  Eigen::Matrix3d mag_axes = Eigen::Matrix3d::Identity();        // R: body -> the magnetometer's axes
  Eigen::Vector3d mag_hard_iron_uT = Eigen::Vector3d::Zero();
  Eigen::Vector3d mag_motor_uT_per_m_s2 = Eigen::Vector3d::Zero();  // m += k (-f_z - g0): the motors' current
  double mag_latency_s = 0.0;                                       // the field of the attitude this much earlier
  Eigen::Vector3d accel_temp_per_degC = Eigen::Vector3d::Zero(), gyro_temp_per_degC = Eigen::Vector3d::Zero();
  Eigen::Vector3d lever_arm_b_m = Eigen::Vector3d::Zero();       // antenna = IMU + C_nb l
  double gps_latency_s = 0.0;                                     // each fix this much older than its stamp
  double gps_velocity_latency_s = 0.0;                            // its velocity this much older than its position
};

inline bool finite_number(const nlohmann::json& v, double& out) {
  if (!v.is_number()) return false;
  out = v.get<double>();
  return std::isfinite(out);
}

/// A time in seconds within 0..max_s.
inline bool read_seconds(const nlohmann::json& v, double max_s, double& out, std::string& why) {
  if (!finite_number(v, out)) {
    why = "expected a finite number of seconds";
    return false;
  }
  if (out < 0.0 || out > max_s) {
    why = fmt::format("{} s is outside 0..{} s", out, max_s);
    return false;
  }
  return true;
}

inline bool read_vector(const nlohmann::json& v, Eigen::Vector3d& out, std::string& why) {
  why = "expected an array of 3 finite numbers";
  if (!v.is_array() || v.size() != 3) return false;
  for (std::size_t i = 0; i < 3; ++i)
    if (!finite_number(v[i], out[static_cast<Eigen::Index>(i)])) return false;
  return true;
}

inline bool read_matrix(const nlohmann::json& v, Eigen::Matrix3d& out, std::string& why) {
  if (!v.is_array() || v.size() != 3) {
    why = "expected a 3x3 array of rows of finite numbers";
    return false;
  }
  for (std::size_t r = 0; r < 3; ++r) {
    Eigen::Vector3d row;
    if (!read_vector(v[r], row, why)) {
      why = "expected a 3x3 array of rows of finite numbers";
      return false;
    }
    out.row(static_cast<Eigen::Index>(r)) = row.transpose();
  }
  return true;
}

/// A misalignment: a 3x3 with a zero diagonal and small angles.
inline bool read_misalignment(const nlohmann::json& v, Eigen::Matrix3d& out, std::string& why) {
  if (!read_matrix(v, out, why)) return false;
  if (out.diagonal().cwiseAbs().maxCoeff() != 0.0) {
    why = "diagonal must be 0 (per-axis scale belongs to *_scale)";
    return false;
  }
  if (out.cwiseAbs().maxCoeff() > 0.2) {
    why = "misalignment above 0.2 rad is not a small angle";
    return false;
  }
  return true;
}

inline nlohmann::json vector_json(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }
inline nlohmann::json matrix_json(const Eigen::Matrix3d& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index r = 0; r < 3; ++r) rows.push_back(vector_json(m.row(r).transpose()));
  return rows;
}

inline Eigen::Vector3d signed_vector(Rng& rng, double lo, double hi) {
  return {rng.signed_uniform(lo, hi), rng.signed_uniform(lo, hi), rng.signed_uniform(lo, hi)};
}

inline Eigen::Matrix3d off_diagonal(Rng& rng, double lo, double hi) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (Eigen::Index r = 0; r < 3; ++r)
    for (Eigen::Index c = 0; c < 3; ++c)
      if (r != c) m(r, c) = rng.signed_uniform(lo, hi);
  return m;
}

inline constexpr double kMrad = 1e-3;
inline constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

}  // namespace sinu::sim::effects
