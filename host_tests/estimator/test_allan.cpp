// Overlapping Allan deviation and noise-term extraction against the closed
// forms of IEEE Std 952 on synthetic rate series with known terms.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <unsupported/Eigen/FFT>
#include <random>
#include <vector>

#include "estimator/noise/allan_deviation.hpp"
#include "estimator/noise/allan_noise_terms.hpp"
#include "estimator/noise/model_allan.hpp"

namespace {

using namespace sinu::noise;

TEST(AllanDeviation, WhiteNoiseFollowsMinusHalfSlopeWithinItsInterval) {
  // White rate noise of density N: ADEV(tau) = N / sqrt(tau).
  const double dt = 0.025, density = 0.003;  // unit/sqrt(Hz)
  const double sigma = density / std::sqrt(dt);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal(0.0, sigma);
  std::vector<double> y(400000);
  for (double& v : y) v = 0.7 + normal(rng);  // the offset must not matter
  const auto curve = overlapping_allan(y, dt, 4);
  ASSERT_GT(curve.size(), 50u);
  int inside = 0;
  for (const AllanPoint& p : curve) {
    const double truth = density / std::sqrt(p.tau_s);
    inside += (truth >= p.adev_low && truth <= p.adev_high) ? 1 : 0;
    EXPECT_LT(p.adev_low, p.adev);
    EXPECT_GT(p.adev_high, p.adev);
  }
  // ~68% intervals: neighbouring taus are correlated, so allow a wide band.
  const double frac = static_cast<double>(inside) / static_cast<double>(curve.size());
  EXPECT_GT(frac, 0.45);
  EXPECT_LT(frac, 0.95);
  // tau = dt: ADEV = sigma exactly in expectation; 400000 samples -> 0.2% std.
  EXPECT_NEAR(curve.front().adev, sigma, 0.01 * sigma);
}

TEST(AllanNoiseTerms, RecoversWhiteNoiseAndRateRandomWalk) {
  // N = 0.002 unit/sqrt(Hz), K = 2e-5 unit/sqrt(s) at 40 Hz for 8 hours of
  // samples would be the bench case; 4 hours keeps the test fast and still
  // gives ~50 clusters at the tau (~7000 s) where RRW dominates.
  const double dt = 0.025, n_true = 0.002, k_true = 2e-5;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> y(576000);
  double walk = 0.0;
  for (double& v : y) {
    walk += k_true * std::sqrt(dt) * normal(rng);
    v = n_true / std::sqrt(dt) * normal(rng) + walk;
  }
  const auto curve = overlapping_allan(y, dt, 4);
  const AllanNoiseTerms t = fit_allan_noise_terms(curve);
  ASSERT_TRUE(t.valid);
  // White density is read from hundreds of well-averaged points: 3%.
  EXPECT_NEAR(t.N, n_true, 0.03 * n_true);
  // RRW rests on the few long-tau points (edf ~ tens): 35%.
  EXPECT_NEAR(t.K, k_true, 0.35 * k_true);
  // No flicker or ramp was simulated: whatever is fitted must stay below the
  // curve minimum (they are not invented to fill the plot).
  EXPECT_LT(t.B_fit * kFlickerAdevFactor, 0.8 * t.B * kFlickerAdevFactor);
  // The model passes through the curve where it is well determined.
  for (const AllanPoint& p : curve) {
    if (p.edf < 100) continue;
    EXPECT_NEAR(t.model_adev(p.tau_s), p.adev, 0.1 * p.adev) << p.tau_s;
  }
}

TEST(AllanNoiseTerms, BiasInstabilityFromFlickerFloor) {
  // Flicker rate noise made by spectral shaping: white Gaussian spectrum
  // scaled by 1/sqrt(f), inverse FFT. IEEE 952: one-sided S(f) = B^2 / (2 pi f)
  // gives the flat AVAR = (2 ln2 / pi) B^2. With one-sided PSD S(f), the
  // rfft bin k (k = 1..n/2-1) of a real series has E|X_k|^2 = S(f_k) fs n / 2.
  const double dt = 0.025, fs = 1.0 / dt, b_true = 5e-4, n_white = 0.001;
  const std::size_t n = 1u << 20;  // 7.3 hours at 40 Hz
  std::mt19937_64 rng(9);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<std::complex<double>> spec(n, 0.0);
  for (std::size_t k = 1; k < n / 2; ++k) {
    const double f = static_cast<double>(k) * fs / static_cast<double>(n);
    const double s = b_true * b_true / (2.0 * std::numbers::pi * f);
    const double amp = std::sqrt(s * fs * static_cast<double>(n) / 2.0 / 2.0);  // per re/im part
    spec[k] = {amp * normal(rng), amp * normal(rng)};
    spec[n - k] = std::conj(spec[k]);
  }
  Eigen::FFT<double> fft;
  std::vector<double> y;
  fft.inv(y, spec);
  for (double& v : y) v += n_white / std::sqrt(dt) * normal(rng);
  const auto curve = overlapping_allan(y, dt, 4);
  const AllanNoiseTerms t = fit_allan_noise_terms(curve);
  ASSERT_TRUE(t.valid);
  // Factor 1.5, the accuracy IEEE 952's read-off-the-floor method is good for
  // (the floor of a finite record wanders by tens of percent).
  EXPECT_LT(t.B / b_true, 1.5);
  EXPECT_GT(t.B / b_true, 1.0 / 1.5);
  EXPECT_LT(t.B_fit / b_true, 1.5);
  EXPECT_GT(t.B_fit / b_true, 1.0 / 1.5);
  // White density: the flicker adds to the short-tau ADEV too, so 10%.
  EXPECT_NEAR(t.N, n_white, 0.10 * n_white);
}

TEST(AllanDeviation, TooShortSeriesGivesEmptyCurve) {
  EXPECT_TRUE(overlapping_allan(std::vector<double>(5, 1.0), 0.025).empty());
  EXPECT_FALSE(fit_allan_noise_terms(std::vector<AllanPoint>{}).valid);
}

// The Allan variance a model predicts, from its autocovariance, against the
// closed forms: white noise sigma^2 / m; a first-order Gauss-Markov process
// of variance q and correlation time T (continuous averaging, e.g. El-Sheimy,
// Hou & Niu 2008): AVAR = q T^2 / tau^2 (2 tau / T - 3 + 4 e^-tau/T - e^-2tau/T).
TEST(ModelAllan, WhiteNoiseAndGaussMarkovAgainstTheirClosedForms) {
  std::vector<double> white(400, 0.0);
  white[0] = 2.5;
  for (const std::size_t m : {1u, 7u, 100u, 200u}) EXPECT_NEAR(allan_variance_of_autocovariance(white, m), 2.5 / static_cast<double>(m), 1e-12);
  EXPECT_TRUE(std::isnan(allan_variance_of_autocovariance(white, 201)));  // needs lags up to 2m - 1

  const double q = 0.04, T = 5.0, dt = 0.005;  // dt = T / 1000: the sums approach the integrals
  std::vector<double> r(static_cast<std::size_t>(200.0 / dt) + 2);
  for (std::size_t k = 0; k < r.size(); ++k) r[k] = q * std::exp(-static_cast<double>(k) * dt / T);
  for (const double tau : {0.5, 2.0, 5.0, 20.0, 90.0}) {
    const auto m = static_cast<std::size_t>(std::lround(tau / dt));
    const double x = tau / T;
    const double closed = q / (x * x) * (2.0 * x - 3.0 + 4.0 * std::exp(-x) - std::exp(-2.0 * x));
    // The discrete sums differ from the continuous integrals by O(dt / T) = 0.1 %.
    EXPECT_NEAR(allan_variance_of_autocovariance(r, m), closed, 5e-3 * closed) << "tau " << tau;
  }
}

}  // namespace
