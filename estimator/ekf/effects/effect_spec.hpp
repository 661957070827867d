#pragma once
// What every effect file declares about itself (effects/*.hpp): the Effect
// it is, its name, how its states are indexed, units, prior, walk, whether
// `sinu diagnose` may try it and the largest value a real unit has. The
// registration (effect_list.hpp) puts the files in one compile-time list;
// effect_vocabulary.hpp derives every table from it.
#include <array>
#include <cstdint>
#include <Eigen/Core>

namespace sinu::est {

/// Every effect, in the order of effect_list.hpp (a static_assert checks it).
enum class Effect : std::uint8_t {
  AccelScale, GyroScale, LeverArm, GpsLatency, AccelTempBias, GyroTempBias, AccelBias, GyroBias,
  GpsPositionBias, MagEarthField, MagHardIron, MagSoftIron, AccelMisalign, GyroMisalign, GyroGSensitivity, MagMisalign,
  GpsVelocityLatency, MagMotorInterference, MagLatency, VehicleMount
};
inline constexpr std::size_t kEffectCount = 20;

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

/// The sensor axis (0..2) component k belongs to: its own for a vector, the
/// row for an off-diagonal or full 3x3; -1 where no single axis owns it.
constexpr Eigen::Index effect_component_axis(Components c, Eigen::Index k) {
  switch (c) {
    case Components::Xyz: return k;
    case Components::OffDiagonal: return kOffDiagonal[static_cast<std::size_t>(k)][0];
    case Components::Matrix: return k / 3;
    case Components::One:
    case Components::Symmetric: return -1;
  }
  return -1;
}

/// The sensor triad an effect acts on: its component i (or row i of a 3x3)
/// belongs to that triad's axis i (a clipped axis freezes it, diagnose asks
/// that axis's excitation).
enum class Triad : std::uint8_t { None, Accel, Gyro };

/// What a flight must record for diagnose to test the effect at all.
enum class Needs : std::uint8_t { Nothing, Temperature, Magnetometer };

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
  Triad triad = Triad::None;        // the sensor triad whose axis i owns component i (or row i)
  Triad excited_by = Triad::None;   // the input that reveals it: component k (column k of a 3x3) by that axis
  Needs needs = Needs::Nothing;
  const char* revealed_by = nullptr;  // what reveals it where no single sensor axis does (diagnose's advice)
  // A property of the unit the model carries from an assumed value (the
  // configured latency and lever arm, a hard iron of zero): the smallest
  // deviation from it worth telling the user [state unit]; 0: never told. A
  // flight that puts the effect this far (and 3 sigma) from it is a diagnosis.
  double report_resolution = 0.0;
};

inline constexpr double kRadToDeg = 57.29577951308232;

/// The values of one effect, read through its components.
struct EffectView {
  const double* v;
  double scalar() const { return v[0]; }
  Eigen::Vector3d vec3() const { return {v[0], v[1], v[2]}; }
  /// OffDiagonal components as a 3x3 with a zero diagonal.
  Eigen::Matrix3d off_diagonal() const {
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
    for (std::size_t k = 0; k < 6; ++k) M(kOffDiagonal[k][0], kOffDiagonal[k][1]) = v[k];
    return M;
  }
  /// Symmetric components D as I + D.
  Eigen::Matrix3d identity_plus_symmetric() const {
    Eigen::Matrix3d S;
    S << 1.0 + v[0], v[3], v[4], v[3], 1.0 + v[1], v[5], v[4], v[5], 1.0 + v[2];
    return S;
  }
  /// Matrix components, row-major.
  Eigen::Matrix3d matrix() const {
    Eigen::Matrix3d M;
    M << v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8];
    return M;
  }
};

/// Where an IMU correction acts, in the order compensate() applies them:
///   f = (I - Ma) (1 - sa) (f_raw - ba - ka dT),  w likewise,  then w -= G f.
enum class ImuStage : std::uint8_t { Offset, Scale, CrossAxis, Coupling };

}  // namespace sinu::est
