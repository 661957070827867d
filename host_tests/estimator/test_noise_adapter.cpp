// The measurement noise learnt from the innovations (estimator/nav/noise_adapter.hpp):
// it must find the true noise, and an update made while the state is still
// uncertain (innovation variance far above the noise) must teach it almost
// nothing. Before that weighting, the first magnetometer update after
// alignment (innovation sigma 10.8 uT against a 1-uT noise) set the learnt
// sigma to its 0.1-uT floor; a 13 % soft iron learnt against it went to a
// 112-uT Earth field (tools/diagnose_eval.py seed 1070).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "estimator/nav/noise_adapter.hpp"

namespace sinu::test {
namespace {

using est::NoiseAdapter;
using est::NoiseAdapterConfig;

// One 3-row update made with the adapter's current sigma: innovations drawn
// with variance hph + true_sigma^2, reported against S = hph + sigma()^2.
est::UpdateResult update(const NoiseAdapter& a, double hph, double true_sigma, std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, std::sqrt(hph + true_sigma * true_sigma));
  est::UpdateResult r;
  r.rows = 3;
  r.accepted = true;
  for (Eigen::Index i = 0; i < 3; ++i) {
    r.innovation(i) = n(rng);
    r.innovation_sigma(i) = std::sqrt(hph + a.sigma() * a.sigma());
  }
  return r;
}

TEST(NoiseAdapter, AnUpdateWhileTheStateIsUncertainTeachesAlmostNothing) {
  NoiseAdapter a;
  a.configure(NoiseAdapterConfig{true, 60.0, 0.1, 5.0}, 1.0);
  est::UpdateResult r;
  r.rows = 3;
  r.innovation = Eigen::Vector3d(-0.002, -0.303, -0.756);  // the first update of seed 1070
  r.innovation_sigma = Eigen::Vector3d::Constant(10.832);
  a.learn(r, 0.1);
  // Its weight is (1 / 10.8^2)^2 = 7e-5 of a sample: the sigma stays where it
  // was configured (the unweighted mean fell to the 0.1 floor).
  EXPECT_NEAR(a.sigma(), 1.0, 0.01);
}

// 0.4-uT noise, configured 1 uT, the state's share of the innovation variance
// falling from 100 uT^2 to 0.01 over the first 100 updates (10 Hz): after
// 10 minutes the learnt sigma is the true one. Tolerance: 6000 updates of 3
// rows over a 60-s (600-update) memory give a variance sampled ~1800 times,
// a relative standard deviation of sqrt(2/1800) = 3 % on the variance, 1.7 %
// on the sigma; 5 % is three of those.
TEST(NoiseAdapter, FindsTheTrueNoiseAsTheStateConverges) {
  std::mt19937 rng(7);
  NoiseAdapter a;
  a.configure(NoiseAdapterConfig{true, 60.0, 0.1, 5.0}, 1.0);
  double lowest = 1.0;
  for (int k = 0; k < 6000; ++k) {
    const double hph = k < 100 ? 100.0 * std::pow(1e-4, k / 100.0) : 0.01;
    a.learn(update(a, hph, 0.4, rng), 0.1);
    lowest = std::min(lowest, a.sigma());
  }
  EXPECT_NEAR(a.sigma(), 0.4, 0.05 * 0.4);
  EXPECT_GT(lowest, 0.3) << "it never undershoots far below the true 0.4 on the way";
}

// A disturbed sensor: innovations five times the noise for a while (all
// rejected by the gate, clipped at 5 sigma) make the learnt sigma grow, so the
// sensor is trusted less rather than ignored for good.
TEST(NoiseAdapter, ADisturbanceRaisesTheSigma) {
  std::mt19937 rng(3);
  NoiseAdapter a;
  a.configure(NoiseAdapterConfig{true, 60.0, 0.1, 5.0}, 0.4);
  for (int k = 0; k < 600; ++k) a.learn(update(a, 0.01, 2.0, rng), 0.1);
  EXPECT_GT(a.sigma(), 1.0);
}

// A receiver without GST: its sigma is guessed as DOP x UERE, the DOP
// changing from fix to fix (here 0.6-3.0), and the truth is 0.8 m per axis
// whatever the DOP (guess / truth 1.3-6.6 and the fix-to-fix spread a
// factor of 5). The factor learnt on the guess must still make each fix's
// sigma the true one on average: the weighted mean of y^2 / guess^2 is k^2.
// 3000 fixes (10 min at 5 Hz) over a 60-s (300-fix) memory of 2 rows: ~600
// samples, 5.8 % on k^2, 2.9 % on k; 10 % is about three of those.
TEST(NoiseAdapter, LearnsTheFactorOnAGuessThatChangesEveryUpdate) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> dop(0.6, 3.0);
  std::normal_distribution<double> unit(0.0, 1.0);
  const double uere = 2.5 / std::sqrt(2.0), truth = 0.8, hph = 0.05;
  NoiseAdapter k;
  k.configure(NoiseAdapterConfig{true, 60.0, 0.2, 4.0}, 1.0);
  for (int n = 0; n < 3000; ++n) {
    const double guess = dop(rng) * uere;
    const double r_used = k.sigma() * guess;  // what the navigator fuses with
    est::UpdateResult r;
    r.rows = 3;  // N, E learnt here; D is another factor's row
    for (Eigen::Index i = 0; i < 3; ++i) {
      r.innovation(i) = std::sqrt(hph + truth * truth) * unit(rng);
      r.innovation_sigma(i) = std::sqrt(hph + r_used * r_used);
      r.noise_sigma(i) = r_used;
    }
    k.learn_scale(r, 0, 2, 0.2);
  }
  // E[y^2 / guess^2] = 0.8^2 E[1/d^2] / uere^2, and E[1/d^2] = 1 / (0.6 x 3) for d uniform on [0.6, 3].
  const double k_expected = truth / (uere * std::sqrt(0.6 * 3.0));
  EXPECT_NEAR(k.sigma(), k_expected, 0.10 * k_expected);
}

}  // namespace
}  // namespace sinu::test
