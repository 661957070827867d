// What a flight excited, as diagnose judges it (replay::Excitation): the
// specific force held for a second or more, not the vibration around it. A
// car's accelerometer z spans more than a g sample to sample on a rough road
// while what a z scale turns into velocity error only follows the sustained
// part; judged on the samples, the real drive's z scale was "driven" and,
// free, wandered to 9 %.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "firmware/host/replay/replay_result.hpp"

namespace sinu::test {
namespace {

constexpr double kG = 9.80665;

/// 100-Hz samples: level, 8-Hz vibration of `vibration_g` on z, and from 10 s
/// to 13 s a pull-up of `pull_g` (z more negative: more lift).
replay::Excitation excite(double vibration_g, double pull_g, bool with_nan = false) {
  replay::Excitation x;
  for (int i = 0; i < 2000; ++i) {
    est::ImuSample s;
    s.t_s = 100.0 + 0.01 * i;
    const double t = 0.01 * i;
    double fz = -kG - vibration_g * kG * std::sin(2.0 * std::numbers::pi * 8.0 * t);
    if (t >= 10.0 && t < 13.0) fz -= pull_g * kG;
    s.specific_force_b_m_s2 = Eigen::Vector3d(0.0, 0.0, fz);
    if (with_nan && i == 700) s.specific_force_b_m_s2.x() = std::numeric_limits<double>::quiet_NaN();
    x.add(s);
  }
  return x;
}

double span_g(const replay::Excitation& x, int axis) { return (x.f_max_m_s2(axis) - x.f_min_m_s2(axis)) / kG; }

TEST(Excitation, VibrationIsNotExcitation) {
  // +-0.6 g at 8 Hz: 1.2 g sample to sample. Through a 1-s low-pass its
  // amplitude is 0.6 / (2 pi 8 s^-1 x 1 s) = 0.012 g, a span of 0.024 g;
  // 0.05 g allows for the phase at the start of the window.
  EXPECT_LT(span_g(excite(0.6, 0.0), 2), 0.05);
}

TEST(Excitation, ASustainedPullUpIs) {
  // 0.3 g for 3 s: the 1-s low-pass reaches 1 - e^-3 = 95 % of it (0.285 g),
  // the vibration adding at most its 0.024 g span.
  const double s = span_g(excite(0.6, 0.3), 2);
  EXPECT_GT(s, 0.27);
  EXPECT_LT(s, 0.32);
}

TEST(Excitation, ANanSampleDoesNotPoisonTheRange) {
  const replay::Excitation x = excite(0.0, 0.3, true);
  EXPECT_TRUE(std::isfinite(span_g(x, 0)));
  EXPECT_LT(span_g(x, 0), 1e-9);  // x never moved
  EXPECT_GT(span_g(x, 2), 0.27);
}

}  // namespace
}  // namespace sinu::test
