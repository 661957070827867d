// A restart's saved state, aged (estimator/nav/warm_start.hpp): what the
// filter's own process model says the saved estimates are worth `age` later.
#include <gtest/gtest.h>

#include <cmath>

#include "estimator/nav/warm_start.hpp"

namespace sinu::est {
namespace {

TEST(WarmStart, AgesEachEffectByItsOwnProcess) {
  EffectTuning tuning;
  SensorNoise noise;
  noise.accel_bias_walk = 2e-4;  // m/s^2 / sqrt(s)
  noise.gyro_bias_walk = 3e-6;   // rad/s / sqrt(s)
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
  set(Effect::GpsPositionBias, 1.5, 0.6);
  w.gps_bias_level_ned_m = {1.2, 1.2, 2.5};
  const double age = 60.0;
  const WarmStart a = aged(w, age, tuning, noise);
  const auto& acc = a.effects[static_cast<std::size_t>(Effect::AccelBias)];
  const auto& gyr = a.effects[static_cast<std::size_t>(Effect::GyroBias)];
  const auto& lat = a.effects[static_cast<std::size_t>(Effect::GpsLatency)];
  const auto& pos = a.effects[static_cast<std::size_t>(Effect::GpsPositionBias)];
  // A random walk keeps its value; its variance grows by q t.
  EXPECT_DOUBLE_EQ(acc.value[0], 0.1);
  EXPECT_NEAR(acc.sigma[0], std::sqrt(0.004 * 0.004 + 2e-4 * 2e-4 * age), 1e-15);
  EXPECT_NEAR(gyr.sigma[2], std::sqrt(1e-8 + 9e-12 * age), 1e-15);
  const double walk = tuning.walk(Effect::GpsLatency);
  EXPECT_NEAR(lat.sigma[0], std::sqrt(0.003 * 0.003 + walk * walk * age), 1e-15);
  // The receiver's first-order GM: the mean decays by exp(-t/tau), the
  // variance relaxes towards the level: s^2 e^-2t/tau + L^2 (1 - e^-2t/tau).
  const double d = std::exp(-age / tuning.gps_bias_tau_s);
  EXPECT_NEAR(pos.value[0], 1.5 * d, 1e-12);
  EXPECT_NEAR(pos.sigma[2], std::sqrt(0.36 * d * d + 6.25 * (1.0 - d * d)), 1e-12);
  // A day later it says nothing any more: the receiver's error is its level.
  const auto& old = aged(w, 86400.0, tuning, noise).effects[static_cast<std::size_t>(Effect::GpsPositionBias)];
  EXPECT_NEAR(old.value[1], 0.0, 1e-12);
  EXPECT_NEAR(old.sigma[1], 1.2, 1e-12);
  // Effects the saved filter did not carry stay absent.
  EXPECT_FALSE(a.effects[static_cast<std::size_t>(Effect::LeverArm)].given);
}

}  // namespace
}  // namespace sinu::est
