// How `sinu diagnose` weighs one candidate's estimate (weigh_estimate): its
// significance against what the baseline assumed, and whether a real unit can
// have the value. Numbers from real candidate replays of the evaluation
// (tools/diagnose_eval.py, seed 1179: an accelerometer scale hidden beside a
// gyro misalignment).
#include <gtest/gtest.h>

#include "firmware/host/diagnose/diagnose_runner.hpp"

namespace sinu::test {
namespace {

using diagnose::CandidateResult;
using diagnose::DiagnoseOptions;

CandidateResult weigh(est::Effect effect, std::vector<double> estimate, std::vector<double> sigma, double gain,
                      const DiagnoseOptions& o = {}) {
  CandidateResult c;
  c.effect = effect;
  c.nll_gain = gain;
  c.evidence_threshold = o.min_log_evidence;
  replay::EffectEstimate e{effect, std::move(estimate), std::move(sigma)};
  diagnose::weigh_estimate(e, est::EffectPrior{}, o, c);
  return c;
}

// The flight turned but never pushed sideways: accelerometer y kept 98 % of its
// prior sigma (0.02) and its estimate wandered to 3.6 % at 1.8 sigma, beyond
// the 3.5 % a real unit has; x is determined (-0.79 %, 3.6 sigma). The flight
// did not ask for the large y, so it must not veto the x it did ask for (this
// pair was reported as one effect found of two).
TEST(WeighEstimate, AnUnexcitedAxisWanderingPastThePlausibleMaximumDoesNotVetoTheEffect) {
  const CandidateResult c =
      weigh(est::Effect::AccelScale, {-0.00794, 0.03586, -0.00315}, {0.00219, 0.01956, 0.00098}, 8.15);
  EXPECT_NEAR(c.significance, 3.63, 0.01);  // |-0.00794| / 0.00219
  EXPECT_NEAR(c.plausibility, 0.00794 / 0.035, 1e-3) << "only the determined component counts";
  EXPECT_TRUE(c.explains(3.0));
}

// The same 3.6 % on y, but determined (3.6 % +- 0.2 %): the data demand a scale
// no real unit has, so the misfit is something else.
TEST(WeighEstimate, ADeterminedValueBeyondThePlausibleMaximumIsAnImplausibleFit) {
  const CandidateResult c =
      weigh(est::Effect::AccelScale, {-0.00794, 0.03586, -0.00315}, {0.00219, 0.002, 0.00098}, 8.15);
  EXPECT_GT(c.plausibility, 1.0);
  EXPECT_FALSE(c.explains(3.0));
  EXPECT_TRUE(c.implausible_fit(3.0));
}

// A lever arm is measured from the configured one, not from zero: a flight
// that confirms the configured 0.5 m is no evidence of a missing lever arm.
TEST(WeighEstimate, ALeverArmIsWeighedAgainstTheConfiguredOne) {
  DiagnoseOptions o;
  o.replay.unit.lever_arm_b_m = Eigen::Vector3d(0.5, 0.0, 0.0);
  EXPECT_LT(weigh(est::Effect::LeverArm, {0.51, 0.0, 0.0}, {0.02, 0.02, 0.02}, 10.0, o).significance, 1.0);
  EXPECT_NEAR(weigh(est::Effect::LeverArm, {0.51, 0.0, 0.0}, {0.02, 0.02, 0.02}, 10.0).significance, 25.5, 1e-9);
}

// Soft iron: a scale common to xx, yy, zz trades against the Earth field's
// strength (a state), so a 13 % common scale alone is no evidence; a 13 %
// difference between axes is.
TEST(WeighEstimate, ASoftIronsCommonScaleIsNoEvidence) {
  const std::vector<double> sigma(6, 0.001);
  EXPECT_LT(weigh(est::Effect::MagSoftIron, {0.13, 0.13, 0.13, 0.0, 0.0, 0.0}, sigma, 50.0).significance, 1e-6);
  const CandidateResult diff = weigh(est::Effect::MagSoftIron, {0.13, 0.0, 0.0, 0.0, 0.0, 0.0}, sigma, 50.0);
  EXPECT_GT(diff.significance, 80.0);  // 0.13 - 0.0433 = 0.087 at 0.001
  EXPECT_TRUE(diff.explains(3.0));
}

}  // namespace
}  // namespace sinu::test
