#pragma once
// Physical effects: the shared vocabulary of `simulate`, `replay --effects`
// and `diagnose`. Each is one file in sim/effects/ (its JSON value, its
// random draw, what it does to the sensor models), registered in
// sim/effects/effect_list.hpp; here the values of a flight, each absent (the
// nominal sensor) or set:
//   accel_scale [ppm x3], gyro_scale [ppm x3]    measured = (1 + s) true, per axis
//   accel_misalign, gyro_misalign [rad, 3x3]     measured = (I + M) true, M off-diagonal
//                                                (M(i,j): axis i senses axis j; diagonal must be 0)
//   lever_arm [m x3, body FRD]                   GPS antenna = IMU + C_nb l (position and velocity)
//   gps_latency [s, 0..1]                        each fix is this much older than its time stamp
//   gps_velocity_latency [s, 0..0.5]             its velocity this much older than its position (true v(t - tau))
//   accel_temp_bias [m/s^2/degC x3]              bias += k (T - 25 degC)
//   gyro_temp_bias [rad/s/degC x3]               bias += k (T - 25 degC)
//   mag_hard_iron [uT x3]                        m += b
//   mag_soft_iron [3x3]                          m = S R m_earth_b (+ hard iron); nominal S = I
//   mag_misalign [rad x3]                        R = exp(-[theta x]): the magnetometer's axes turned by theta
//   mag_motor_interference [uT per m/s^2 x3]     m += k (-f_z - g0): the motors' current, with the thrust
//   mag_latency [s]                              the field of the attitude tau before the stamp
//   gyro_g_sensitivity [rad/s per m/s^2, 3x3]    gyro += G f_b (true specific force)
// JSON: {"lever_arm": [0.6, -0.2, -0.4], "gps_latency": 0.15,
//        "gyro_g_sensitivity": [[..],[..],[..]], ...}; 3x3 values are arrays of rows.
#include <Eigen/Core>
#include <array>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "firmware/host/dataset/diagnostic.hpp"
#include "firmware/host/sim/effects/effect_value.hpp"
#include "firmware/host/sim/rng.hpp"

namespace sinu::sim {

inline constexpr double kTempBiasReference_degC = 25.0;

struct Effects {
  std::optional<Eigen::Vector3d> accel_scale_ppm{}, gyro_scale_ppm{};
  std::optional<Eigen::Matrix3d> accel_misalign_rad{}, gyro_misalign_rad{};
  std::optional<Eigen::Vector3d> lever_arm_b_m{};
  std::optional<double> gps_latency_s{};
  std::optional<double> gps_velocity_latency_s{};
  std::optional<Eigen::Vector3d> accel_temp_bias_m_s2_per_degC{}, gyro_temp_bias_rad_s_per_degC{};
  std::optional<Eigen::Vector3d> mag_hard_iron_uT{};
  std::optional<Eigen::Matrix3d> mag_soft_iron{};
  std::optional<Eigen::Vector3d> mag_misalign_rad{};
  std::optional<Eigen::Vector3d> mag_motor_uT_per_m_s2{};
  std::optional<double> mag_latency_s{};
  std::optional<Eigen::Matrix3d> gyro_g_sensitivity_rad_s_per_m_s2{};

  std::size_t count() const;
};

/// Parses an effects object. On failure `err` names `file` and the key.
bool parse_effects(const nlohmann::json& j, const std::string& file, Effects& out, dataset::Diagnostic& err);
/// Reads and parses an effects JSON file.
bool read_effects_file(const std::string& path, Effects& out, dataset::Diagnostic& err);
/// The effects as JSON, in the same form parse_effects() reads.
nlohmann::json effects_to_json(const Effects& e);
/// Draws `k` distinct effects (k <= kEffectCount) with magnitudes large enough to matter.
Effects draw_random_effects(std::size_t k, Rng& rng);
/// The unit's own accelerometer scale factors (up to +-15000 ppm per axis) and
/// misalignment (off-diagonal terms up to +-15 mrad), drawn from `rng` (stream
/// UnitAccelErrors of the seed: a flight and a bench session of one seed are
/// one unit); each fills `e` only where it has no value yet.
void draw_unit_accel_errors(Rng& rng, Effects& e);
/// What the effects do to the sensor models (ImuSensor, GpsReceiver).
effects::SensorEffects sensor_effects(const Effects& e);
// The vocabulary's names, in the registration's order: kEffectNames in sim/effects/effect_list.hpp.

}  // namespace sinu::sim
