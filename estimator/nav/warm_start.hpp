#pragma once
// What a navigator has learnt that outlives its solution, for a unit that
// restarts in the air (the companion computer rebooted, the process was
// restarted): every effect state's value and sigma (the turn-on biases, the
// receiver's latency and correlated error, the hard iron, ...), the
// temperature they refer to and the noise levels learnt from the
// innovations, and what vehicle carries the unit. The attitude, velocity
// and position are not in it: a restarted unit aligns again, in motion, and
// takes these as its priors, aged; what a power cycle or a battery swap
// changes only where the data say it has not changed (checked_by_the_field,
// checked_by_the_rest below).
// The board keeps it in a state file (firmware/board/state_file.hpp).
#include <array>
#include <Eigen/Core>

#include "estimator/ekf/effect_tuning.hpp"
#include "estimator/ekf/vehicle_axes.hpp"

namespace sinu::est {

struct WarmStart {
  bool given = false;
  std::array<EffectPrior, kEffectCount> effects{};  // given for every effect the saved filter carried
  double temp_ref_degC = 0.0;                       // the temperature coefficients' reference
  Eigen::Vector3d gps_bias_level_ned_m = Eigen::Vector3d::Zero();  // the receiver GM's sigma (0: unknown)
  double gnss_velocity_sigma_m_s = 0.0;             // learnt noise levels (0: unknown)
  double mag_sigma_uT = 0.0;
  Eigen::Vector2d gnss_white_scale = Eigen::Vector2d::Zero();     // horizontal, vertical
  Eigen::Vector2d gnss_position_scale = Eigen::Vector2d::Zero();
  // What the vehicle detector found (vehicle = auto): the vehicle that
  // carries the unit outlives a reboot. A restart in motion takes it at once
  // (the non-holonomic constraint from the alignment, still reverted if it
  // fails) instead of after 20 s of driving and a turn. The axes have the
  // vehicle_mount estimate turned in.
  bool ground_vehicle = false;
  bool on_bracket = false;
  VehicleAxes vehicle_axes;
};

/// The same, `age_s` later, as a restart's priors: each effect's sigma grown
/// by its random walk over the age; the receiver's correlated error decayed
/// towards zero and its variance towards the GM's level (tau from the
/// tuning).
WarmStart aged(const WarmStart& w, double age_s, const EffectTuning& tuning);

/// The turn-on biases (accel_bias, gyro_bias), which a power cycle draws
/// anew and a reboot keeps: a restart keeps them only when it aligns at rest
/// and the rest measures the saved gyro bias and the saved accelerometer bias
/// along gravity again (within 3 sigma). Then the saved accelerometer bias
/// across gravity, which no rest can tell from a tilt, levels the unit. In
/// motion nothing checks them and they stay out: kept regardless, a gyro
/// bias that had moved by 0.3 deg/s flew with 0.44 deg of attitude error,
/// cold 0.25; one of 1.1 deg/s was reset.
bool checked_by_the_rest(Effect e);

/// The magnetometer's iron (mag_hard_iron, mag_soft_iron,
/// mag_motor_interference), which a battery or payload swap moves: a restart
/// keeps it only to align at rest, where the field it corrects is the
/// Earth's (the navigator's alignment then reads the field through it first,
/// and the field as read only when it does not). In motion the GNSS gives
/// the heading and it stays out: kept regardless, a hard iron 15 uT off
/// turned the attitude 13 deg and was reset (cold 0.4 deg).
bool checked_by_the_field(Effect e);

/// A restart's prior, component k: kept where tighter than what the unit
/// would start from without it (cold_value, cold_sigma), else that: a saved
/// sigma that has grown past it is no knowledge.
void keep_tighter(EffectPrior& saved, std::size_t k, double cold_value, double cold_sigma);

}  // namespace sinu::est
