#pragma once
// The registration: every effect file, once, in the order of enum Effect.
// A new physical effect is its file in effects/ plus a line here and its name
// in enum Effect (effect_spec.hpp); everything else (state layout, tuning,
// names, units, nav.csv columns, the IMU compensation, the error dynamics,
// each aiding source's Jacobian, diagnose's candidates) follows from them.
#include <cstddef>
#include <utility>

#include "estimator/ekf/effects/accel_bias.hpp"
#include "estimator/ekf/effects/accel_misalign.hpp"
#include "estimator/ekf/effects/accel_scale.hpp"
#include "estimator/ekf/effects/accel_temp_bias.hpp"
#include "estimator/ekf/effects/gps_latency.hpp"
#include "estimator/ekf/effects/gps_position_bias.hpp"
#include "estimator/ekf/effects/gps_velocity_latency.hpp"
#include "estimator/ekf/effects/gyro_bias.hpp"
#include "estimator/ekf/effects/gyro_g_sensitivity.hpp"
#include "estimator/ekf/effects/gyro_misalign.hpp"
#include "estimator/ekf/effects/gyro_scale.hpp"
#include "estimator/ekf/effects/gyro_temp_bias.hpp"
#include "estimator/ekf/effects/lever_arm.hpp"
#include "estimator/ekf/effects/mag_earth_field.hpp"
#include "estimator/ekf/effects/mag_hard_iron.hpp"
#include "estimator/ekf/effects/mag_latency.hpp"
#include "estimator/ekf/effects/mag_misalign.hpp"
#include "estimator/ekf/effects/mag_motor_interference.hpp"
#include "estimator/ekf/effects/mag_soft_iron.hpp"
#include "estimator/ekf/effects/vehicle_mount.hpp"

namespace sinu::est {

template <class... E>
struct EffectList {
  static constexpr std::size_t size = sizeof...(E);
  /// f.template operator()<E>() for every effect, in order.
  template <class F> static constexpr void for_each(F&& f) { (f.template operator()<E>(), ...); }
};

using AllEffects = EffectList<effects::AccelScale, effects::GyroScale, effects::LeverArm, effects::GpsLatency,
                              effects::AccelTempBias, effects::GyroTempBias, effects::AccelBias, effects::GyroBias,
                              effects::GpsPositionBias, effects::MagEarthField, effects::MagHardIron,
                              effects::MagSoftIron, effects::AccelMisalign, effects::GyroMisalign,
                              effects::GyroGSensitivity, effects::MagMisalign,
                              effects::GpsVelocityLatency, effects::MagMotorInterference, effects::MagLatency,
                              effects::VehicleMount>;
static_assert(AllEffects::size == kEffectCount, "every Effect has its file in AllEffects");

/// Calls f.template operator()<E>() for every registered effect, in enum order.
template <class F> constexpr void for_each_effect(F&& f) { AllEffects::for_each(std::forward<F>(f)); }

}  // namespace sinu::est
