#pragma once
// The effect vocabulary: every physical effect the EKF can carry as states,
// one row each (name, components, unit, prior, walk, whether `sinu diagnose`
// tries it). Everything else that lists effects (the state layout, the tuning,
// nav.csv's columns, the diagnosis report's units, the default candidates) is
// derived from this table; a static_assert keeps it in enum order. The same
// names are the simulator's (firmware/host/sim/effects.hpp; a test checks that
// every effect it can hide has a row here).
//
// Error states are "true - estimated" and feedback adds them to the estimate.
// The IMU is corrected (ErrorStateFilter::compensate) as
//   f = (I - Ma) (1 - sa) (f_raw - ba - ka dT)
//   w = (I - Mg) (1 - sg) (w_raw - bg - kg dT) - G f
// Ma, Mg: misalignment, off-diagonal only (M(i,j): axis i senses axis j; the
// diagonal is the scale's); G: gyro g-sensitivity, full 3x3.
#include <array>
#include <cstdint>
#include <Eigen/Core>

namespace sinu::est {

enum class Effect : std::uint8_t {
  AccelScale, GyroScale, LeverArm, GpsLatency, AccelTempBias, GyroTempBias, AccelBias, GyroBias,
  GpsPositionBias, MagEarthField, MagHardIron, MagSoftIron, AccelMisalign, GyroMisalign, GyroGSensitivity
};
inline constexpr std::size_t kEffectCount = 15;

/// How an effect's states are indexed.
enum class Components : std::uint8_t {
  One,          // a scalar
  Xyz,          // a vector: x, y, z
  Symmetric,    // a symmetric 3x3 deviation: xx, yy, zz, xy, xz, yz
  OffDiagonal,  // the off-diagonal of a 3x3: xy, xz, yx, yz, zx, zy
  Matrix,       // a full 3x3, row-major: xx, xy, xz, yx, ... zz
};

constexpr Eigen::Index component_count(Components c) {
  switch (c) {
    case Components::One: return 1;
    case Components::Xyz: return 3;
    case Components::Symmetric:
    case Components::OffDiagonal: return 6;
    case Components::Matrix: return 9;
  }
  return 0;
}

/// Row and column of component k of an OffDiagonal effect.
constexpr std::array<std::array<Eigen::Index, 2>, 6> kOffDiagonal = {{{0, 1}, {0, 2}, {1, 0}, {1, 2}, {2, 0}, {2, 1}}};

struct EffectSpec {
  Effect effect;
  const char* name;         // the vocabulary's name (CLI, nav.csv, JSON, the simulator)
  Components components;
  const char* unit;         // as shown to a person
  double display_scale;     // state unit -> shown unit
  double initial_sigma;     // prior [state unit]
  double random_walk;       // [state unit / sqrt(s)]
  bool diagnose_candidate;  // `sinu diagnose` tries adding it (the rest are carried by default)
  double plausible_max;     // the largest |component| a real unit has [state unit]: beyond it, not this effect
};

inline constexpr double kRadToDeg = 57.29577951308232;

// Priors cover consumer MEMS and the simulator's "large enough to matter" draws.
// Plausible maxima (what diagnose accepts as this effect): scale 3.5 % (the
// ICM-20948 states +-1.5 %, the simulator draws up to 3 %), misalignment 35 mrad (2 %
// cross-axis), g-sensitivity 0.5 deg/s/g, temperature coefficients 0.02
// m/s^2/degC and 0.1 deg/s/degC, a lever arm of 3 m, a latency of 0.6 s,
// soft iron 30 %.
inline constexpr std::array<EffectSpec, kEffectCount> kEffects = {{
    {Effect::AccelScale, "accel_scale", Components::Xyz, "ppm", 1e6, 0.02, 1e-6, true, 0.035},
    {Effect::GyroScale, "gyro_scale", Components::Xyz, "ppm", 1e6, 0.02, 1e-6, true, 0.035},
    {Effect::LeverArm, "lever_arm", Components::Xyz, "m", 1.0, 1.0, 0.0, true, 3.0},
    // serial NMEA: 0.02-0.2 s after the fix
    {Effect::GpsLatency, "gps_latency", Components::One, "s", 1.0, 0.1, 1e-4, true, 0.6},
    {Effect::AccelTempBias, "accel_temp_bias", Components::Xyz, "m/s^2/degC", 1.0, 0.01, 1e-7, true, 0.02},
    {Effect::GyroTempBias, "gyro_temp_bias", Components::Xyz, "deg/s/degC", kRadToDeg, 1e-3, 1e-8, true, 2e-3},
    // turn-on biases, ICM-20948 class: +-0.06..0.2 m/s^2, 0.6 deg/s (walks: the sensor model's)
    {Effect::AccelBias, "accel_bias", Components::Xyz, "m/s^2", 1.0, 0.1, 2e-5, false, 2.0},
    {Effect::GyroBias, "gyro_bias", Components::Xyz, "deg/s", kRadToDeg, 0.01, 2e-6, false, 0.2},
    // the receiver's slow error: a GM process (EffectTuning), its sigma from the fixes
    {Effect::GpsPositionBias, "gps_position_bias", Components::Xyz, "m", 1.0, 1.5, 0.0, false, 50.0},
    // set from the attitude at magnetometer start-up; ~0.1 uT over 100 km
    {Effect::MagEarthField, "mag_earth_field", Components::Xyz, "uT", 1.0, 5.0, 1e-3, false, 100.0},
    // a nearby motor or battery: tens of uT (re-anchored on the first field sample)
    {Effect::MagHardIron, "mag_hard_iron", Components::Xyz, "uT", 1.0, 30.0, 1e-2, false, 500.0},
    // steel nearby: up to ~20 %
    {Effect::MagSoftIron, "mag_soft_iron", Components::Symmetric, "-", 1.0, 0.2, 0.0, true, 0.3},
    // cross-axis sensitivity of consumer MEMS: up to ~2 % (20 mrad)
    {Effect::AccelMisalign, "accel_misalign", Components::OffDiagonal, "mrad", 1e3, 0.02, 0.0, true, 0.035},
    {Effect::GyroMisalign, "gyro_misalign", Components::OffDiagonal, "mrad", 1e3, 0.02, 0.0, true, 0.035},
    // MEMS gyros: 0.01-0.2 deg/s per g (5e-4 rad/s per m/s^2 = 0.28 deg/s/g)
    {Effect::GyroGSensitivity, "gyro_g_sensitivity", Components::Matrix, "deg/s/g", kRadToDeg * 9.80665, 5e-4, 0.0,
     true, 9e-4},
}};

constexpr bool vocabulary_in_enum_order() {
  for (std::size_t i = 0; i < kEffectCount; ++i)
    if (static_cast<std::size_t>(kEffects[i].effect) != i) return false;
  return true;
}
static_assert(vocabulary_in_enum_order(), "kEffects must list every Effect once, in enum order");

constexpr const EffectSpec& spec(Effect e) { return kEffects[static_cast<std::size_t>(e)]; }

inline constexpr std::array<const char*, kEffectCount> kEffectNames = [] {
  std::array<const char*, kEffectCount> a{};
  for (std::size_t i = 0; i < kEffectCount; ++i) a[i] = kEffects[i].name;
  return a;
}();
inline constexpr std::array<Eigen::Index, kEffectCount> kEffectDims = [] {
  std::array<Eigen::Index, kEffectCount> a{};
  for (std::size_t i = 0; i < kEffectCount; ++i) a[i] = component_count(kEffects[i].components);
  return a;
}();
inline constexpr Eigen::Index kMaxEffectStates = [] {
  Eigen::Index n = 0;
  for (const Eigen::Index d : kEffectDims) n += d;
  return n;
}();

/// Name of component i of an effect's states ("" for a scalar).
const char* effect_component_name(Effect e, Eigen::Index i);

/// Looks an effect up by its vocabulary name; false if unknown.
bool effect_from_name(const char* name, std::size_t length, Effect& out);

}  // namespace sinu::est
