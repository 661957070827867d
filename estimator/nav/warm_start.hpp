#pragma once
// What a navigator has learnt that outlives its solution, for a unit that
// restarts in the air (the companion computer rebooted, the process was
// restarted): every effect state's value and sigma (the turn-on biases, the
// receiver's latency and correlated error, the hard iron, ...), the
// temperature they refer to and the noise levels learnt from the
// innovations. The attitude, velocity and position are not in it: a
// restarted unit aligns again, in motion, and takes these as its priors.
// The board keeps it in a state file (firmware/board/state_file.hpp).
#include <array>
#include <Eigen/Core>

#include "estimator/ekf/effect_tuning.hpp"

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
};

/// The same, `age_s` later, as a restart's priors: each effect's sigma grown
/// by its random walk over the age; the receiver's correlated error decayed
/// towards zero and its variance towards the GM's level (tau from the
/// tuning). The turn-on biases (accel_bias, gyro_bias) are left out: a
/// restart cannot tell whether the IMU lost power with the computer, and a
/// power cycle draws them anew (a restart that kept a 0.3-deg/s gyro bias
/// which had moved by 0.3 deg/s flew its first minutes with 0.44 deg of
/// attitude error, cold 0.25; one of 1.1 deg/s was reset). They come back
/// within a minute of flight; the state file still records them.
WarmStart aged(const WarmStart& w, double age_s, const EffectTuning& tuning);

}  // namespace sinu::est
