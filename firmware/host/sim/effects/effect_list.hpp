#pragma once
// The registration: every simulated effect's file, once. A new effect is its
// file in sim/effects/ (name, JSON value, draw, what it does to the sensor
// models, the member of Effects that holds a flight's value) plus a line here
// and that member; parsing, JSON, random draws and the sensor models follow.
#include <array>
#include <string_view>
#include <utility>

#include "firmware/host/sim/effects/accel_misalign.hpp"
#include "firmware/host/sim/effects/accel_scale.hpp"
#include "firmware/host/sim/effects/accel_temp_bias.hpp"
#include "firmware/host/sim/effects/gps_latency.hpp"
#include "firmware/host/sim/effects/gps_velocity_latency.hpp"
#include "firmware/host/sim/effects/gyro_g_sensitivity.hpp"
#include "firmware/host/sim/effects/gyro_misalign.hpp"
#include "firmware/host/sim/effects/gyro_scale.hpp"
#include "firmware/host/sim/effects/gyro_temp_bias.hpp"
#include "firmware/host/sim/effects/lever_arm.hpp"
#include "firmware/host/sim/effects/mag_hard_iron.hpp"
#include "firmware/host/sim/effects/mag_latency.hpp"
#include "firmware/host/sim/effects/mag_misalign.hpp"
#include "firmware/host/sim/effects/mag_motor_interference.hpp"
#include "firmware/host/sim/effects/mag_soft_iron.hpp"

namespace sinu::sim {

template <class... E>
struct SimEffectList {
  static constexpr std::size_t size = sizeof...(E);
  static constexpr std::array<std::string_view, size> names = {E::name...};
  /// f.template operator()<E>() for every effect, in order.
  template <class F> static constexpr void for_each(F&& f) { (f.template operator()<E>(), ...); }
};

// The order is the random draw's (draw_random_effects shuffles these indices).
using AllSimEffects =
    SimEffectList<effects::AccelScale, effects::GyroScale, effects::AccelMisalign, effects::GyroMisalign,
                  effects::LeverArm, effects::GpsLatency, effects::AccelTempBias, effects::GyroTempBias,
                  effects::MagHardIron, effects::MagSoftIron, effects::GyroGSensitivity,
                  effects::MagMisalign, effects::GpsVelocityLatency, effects::MagMotorInterference,
                  effects::MagLatency>;

inline constexpr std::array<std::string_view, AllSimEffects::size> kEffectNames = AllSimEffects::names;

template <class F> constexpr void for_each_sim_effect(F&& f) { AllSimEffects::for_each(std::forward<F>(f)); }

}  // namespace sinu::sim
