// A restart's saved state, aged (estimator/nav/warm_start.hpp): what the
// filter's own process model says the saved estimates are worth `age` later.
#include <gtest/gtest.h>

#include <cmath>

#include "estimator/nav/warm_start.hpp"

namespace sinu::est {
namespace {

TEST(WarmStart, AgesEachEffectByItsOwnProcess) {
  EffectTuning tuning;
  WarmStart w;
  w.given = true;
  const auto set = [&](Effect e, double value, double sigma) {
    EffectPrior& p = w.effects[static_cast<std::size_t>(e)];
    p.given = true;
    p.value.fill(value);
    p.sigma.fill(sigma);
  };
  set(Effect::AccelBias, 0.1, 0.004);
  set(Effect::GyroBias, -0.002, 1e-4);
  set(Effect::GpsLatency, 0.08, 0.003);
  set(Effect::GyroScale, 0.01, 0.002);
  set(Effect::GpsPositionBias, 1.5, 0.6);
  set(Effect::MagHardIron, 12.0, 0.2);
  w.gps_bias_level_ned_m = {1.2, 1.2, 2.5};
  const double age = 60.0;
  const WarmStart a = aged(w, age, tuning);
  const auto& lat = a.effects[static_cast<std::size_t>(Effect::GpsLatency)];
  const auto& scale = a.effects[static_cast<std::size_t>(Effect::GyroScale)];
  const auto& pos = a.effects[static_cast<std::size_t>(Effect::GpsPositionBias)];
  // A random walk keeps its value; its variance grows by q t.
  EXPECT_DOUBLE_EQ(lat.value[0], 0.08);
  const double walk = tuning.walk(Effect::GpsLatency);
  EXPECT_NEAR(lat.sigma[0], std::sqrt(0.003 * 0.003 + walk * walk * age), 1e-15);
  const double scale_walk = tuning.walk(Effect::GyroScale);
  EXPECT_DOUBLE_EQ(scale.value[2], 0.01);
  EXPECT_NEAR(scale.sigma[2], std::sqrt(0.002 * 0.002 + scale_walk * scale_walk * age), 1e-15);
  // The receiver's first-order GM: the mean decays by exp(-t/tau), the
  // variance relaxes towards the level: s^2 e^-2t/tau + L^2 (1 - e^-2t/tau).
  const double d = std::exp(-age / tuning.gps_bias_tau_s);
  EXPECT_NEAR(pos.value[0], 1.5 * d, 1e-12);
  EXPECT_NEAR(pos.sigma[2], std::sqrt(0.36 * d * d + 6.25 * (1.0 - d * d)), 1e-12);
  // A day later it says nothing any more: the receiver's error is its level.
  const WarmStart day = aged(w, 86400.0, tuning);
  const auto& old = day.effects[static_cast<std::size_t>(Effect::GpsPositionBias)];
  EXPECT_NEAR(old.value[1], 0.0, 1e-12);
  EXPECT_NEAR(old.sigma[1], 1.2, 1e-12);
  // Effects the saved filter did not carry stay absent.
  EXPECT_FALSE(a.effects[static_cast<std::size_t>(Effect::LeverArm)].given);
  // The turn-on biases are aged like any walk and offered to a rest
  // alignment, which keeps them only where it measures them again (the IMU
  // may have lost power: checked_by_the_rest).
  const auto& accel = a.effects[static_cast<std::size_t>(Effect::AccelBias)];
  ASSERT_TRUE(accel.given);
  EXPECT_TRUE(checked_by_the_rest(Effect::AccelBias));
  EXPECT_TRUE(checked_by_the_rest(Effect::GyroBias));
  EXPECT_FALSE(checked_by_the_rest(Effect::MagHardIron));
  EXPECT_DOUBLE_EQ(accel.value[0], 0.1);
  const double accel_walk = tuning.walk(Effect::AccelBias);
  EXPECT_NEAR(accel.sigma[0], std::sqrt(0.004 * 0.004 + accel_walk * accel_walk * age), 1e-15);
  // The iron is aged like any walk and offered to the alignment, which keeps
  // it only where the field says it has not moved (checked_by_the_field).
  const auto& iron = a.effects[static_cast<std::size_t>(Effect::MagHardIron)];
  ASSERT_TRUE(iron.given);
  EXPECT_TRUE(checked_by_the_field(Effect::MagHardIron));
  EXPECT_FALSE(checked_by_the_field(Effect::GpsLatency));
  EXPECT_DOUBLE_EQ(iron.value[1], 12.0);
  const double iron_walk = tuning.walk(Effect::MagHardIron);
  EXPECT_NEAR(iron.sigma[1], std::sqrt(0.04 + iron_walk * iron_walk * age), 1e-12);
}

}  // namespace
}  // namespace sinu::est
