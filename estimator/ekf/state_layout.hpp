#pragma once
// The error-state vector: navigation errors, sensor-error states, optional
// effect states. The maximum dimension is fixed at compile time; the active
// layout (model order, chosen effects) is built at run time. Every block is a
// named Slice: code indexes P through slices, never by bare numbers.
//
// Sign conventions (all blocks are "x_hat - x" except the sensor part):
//   pos  d_p  NED metres of (computed - true) position
//   vel  d_v  computed - true NED velocity [m/s]
//   att  phi  C_nb_hat = (I - [phi x]) C_nb  [rad]
//   sensor states, scale, temperature coefficients, lever arm, latency:
//        true - estimated (feedback adds them to the estimate)
//   mag_earth_field  e = dF + [F_hat x] phi, dF = F - F_hat: the field's error
//        as the body's attitude estimate sees it. A rotation of the whole
//        solution (attitude and field together) leaves e unchanged, so the
//        magnetometer, which cannot see such a rotation while the field is a
//        state, never claims absolute attitude: that information comes from
//        gravity and GNSS motion only. (With dF instead, every field update
//        turned the unobservable direction and the filter grew confident of
//        a heading it could not know: 20 -> 4 deg in a second at rest.)
#include <array>
#include <bitset>
#include <cstdint>
#include <initializer_list>
#include <Eigen/Core>

#include "estimator/ekf/effect_vocabulary.hpp"

namespace sinu::est {

inline constexpr Eigen::Index kNavStates = 9;
inline constexpr Eigen::Index kMaxArOrder = 4;
inline constexpr Eigen::Index kSensorAxes = 6;  // ax ay az gx gy gz

namespace sensor_axis {
enum : Eigen::Index { ax, ay, az, gx, gy, gz };
inline constexpr Eigen::Index kFirstAccel = ax;
inline constexpr Eigen::Index kFirstGyro = gx;
}  // namespace sensor_axis

// Optional effect states: estimator/ekf/effect_vocabulary.hpp (one row each).
// accel_bias / gyro_bias are random-constant (turn-on) biases: calib.json's
// GM/AR models describe the zero-mean part of the error of a static session,
// so a unit's per-power-on bias needs its own states.
// gps_position_bias: the receiver's slowly varying position error (first-order
// GM, NED; atmosphere, multipath, orbit errors) that a GST sigma does not
// separate from its white part.
// mag_earth_field (NED) and mag_hard_iron (body): the magnetometer's model
// m_b = C_bn F_n + h_b; the Earth field is a state so the declination and
// inclination need not be known (PX4 EKF2 does the same).
// mag_soft_iron: the symmetric deviation D of the soft-iron matrix S = I + D,
// m_b = (I + D) C_bn F_n + h_b; states D_xx, D_yy, D_zz, D_xy, D_xz, D_yz.

inline constexpr Eigen::Index kMaxStates = kNavStates + kSensorAxes * kMaxArOrder + kMaxEffectStates;

using StateVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxStates, 1>;
using StateMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxStates, kMaxStates>;

/// A set of states (bit = state index): the states a measurement may not correct.
using StateMask = std::bitset<static_cast<std::size_t>(kMaxStates)>;

struct Slice {
  Eigen::Index start = 0;
  Eigen::Index size = 0;
  bool active() const { return size > 0; }
};

/// A set of effects (bit i = Effect i).
struct EffectSet {
  std::uint32_t bits = 0;
  bool has(Effect e) const { return (bits >> static_cast<unsigned>(e)) & 1u; }
  void add(Effect e) { bits |= 1u << static_cast<unsigned>(e); }
  void remove(Effect e) { bits &= ~(1u << static_cast<unsigned>(e)); }
  static EffectSet of(std::initializer_list<Effect> effects) {
    EffectSet s;
    for (const Effect e : effects) s.add(e);
    return s;
  }
};

/// Where every state lives. Effects can be deferred (PX4 EKF2 reserves its
/// magnetometer states the same way): their slices are reserved after all
/// others but stay inactive, outside `dim`, until activate() switches them
/// on (the magnetometer's first sample; a unit found on a bracket), so nothing has to read
/// the data ahead to decide the layout and nothing pays for unused states.
struct StateLayout {
  Slice pos, vel, att;
  Slice sensor;              // kSensorAxes blocks of `order` states each
  Eigen::Index order = 1;    // states per sensor axis: 1 (GM) or p (AR(p))
  std::array<Slice, kEffectCount> effect{};    // active effects
  std::array<Slice, kEffectCount> reserved{};  // deferred effects, not yet active
  Eigen::Index dim = 0;      // active states

  /// First state of a sensor axis block: the axis's current error.
  Eigen::Index sensor_state(Eigen::Index axis) const { return sensor.start + axis * order; }
  const Slice& of(Effect e) const { return effect[static_cast<std::size_t>(e)]; }
  bool has(Effect e) const { return of(e).active(); }
  /// Active, or reserved for activation.
  bool carries(Effect e) const { return has(e) || reserved[static_cast<std::size_t>(e)].active(); }
  bool has_deferred(EffectSet which) const;
  /// Switches the deferred effects of `which` on: they take the next slices
  /// (dim grows), the rest stay reserved after them.
  void activate(EffectSet which);

  /// order in 1..kMaxArOrder; `deferred` effects (also in `effects` or not)
  /// are reserved at the end and inactive until activate().
  static StateLayout make(Eigen::Index order, EffectSet effects, EffectSet deferred = {});
};

}  // namespace sinu::est
