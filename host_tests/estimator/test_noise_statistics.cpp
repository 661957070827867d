// Autocorrelation, first-order Gauss-Markov fit, the AR model's implied
// autocorrelation and PSD, and order selection, against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "estimator/noise/ar_burg.hpp"
#include "estimator/noise/ar_model.hpp"
#include "estimator/noise/autocorrelation.hpp"
#include "estimator/noise/gauss_markov.hpp"
#include "estimator/noise/mean_removal.hpp"
#include "estimator/noise/order_selection.hpp"

namespace {

using namespace sinu::noise;

std::vector<double> simulate_ar(const std::vector<double>& a, double sigma, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  const std::size_t warm = 5000;
  std::vector<double> x(n + warm, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    double v = normal(rng);
    for (std::size_t k = 1; k < a.size() && k <= i; ++k) v -= a[k] * x[i - k];
    x[i] = v;
  }
  return {x.begin() + warm, x.end()};
}

TEST(Autocorrelation, FftEqualsDirectSumBiasedAndUnbiased) {
  const std::vector<double> x = simulate_ar({1.0, -0.9}, 1.0, 5000, 1);
  for (AcfScale s : {AcfScale::Biased, AcfScale::Unbiased}) {
    const auto direct = autocorrelation_direct(x, 300, s);
    const auto fft = autocorrelation_fft(x, 300, s);
    ASSERT_EQ(direct.size(), 301u);
    ASSERT_EQ(fft.size(), 301u);
    // FFT round-off grows like log2(nfft) * eps * sum x^2: 1e-12 of r(0) is
    // ~1000x that bound and far below any statistical meaning.
    for (std::size_t k = 0; k <= 300; ++k) EXPECT_NEAR(fft[k], direct[k], 1e-12 * direct[0]) << k;
  }
  // Unbiased = biased * N / (N - k).
  const auto b = autocorrelation(x, 100, AcfScale::Biased);
  const auto u = autocorrelation(x, 100, AcfScale::Unbiased);
  EXPECT_NEAR(u[100], b[100] * 5000.0 / 4900.0, 1e-12 * b[0]);
  EXPECT_DOUBLE_EQ(u[0], b[0]);
}

TEST(Autocorrelation, HandCheckedSmallSeries) {
  const std::vector<double> x{1.0, 2.0, 3.0};
  const auto r = autocorrelation(x, 5, AcfScale::Biased);  // max_lag clipped to N-1
  ASSERT_EQ(r.size(), 3u);
  EXPECT_DOUBLE_EQ(r[0], 14.0 / 3.0);
  EXPECT_DOUBLE_EQ(r[1], 8.0 / 3.0);
  EXPECT_DOUBLE_EQ(r[2], 3.0 / 3.0);
  EXPECT_TRUE(autocorrelation(std::vector<double>{}, 3, AcfScale::Biased).empty());
}

TEST(MeanRemoval, ReturnsTurnOnBiasAndZeroMeanSeries) {
  std::vector<double> x(1000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = -9.80665 + 1e-3 * std::sin(0.1 * static_cast<double>(i));
  double bias = 0.0;
  const auto centred = remove_mean(x, bias);
  EXPECT_NEAR(bias, series_mean(x), 1e-15);
  EXPECT_NEAR(bias, -9.80665, 1e-5);  // the sine averages to ~0 over 16 periods
  EXPECT_NEAR(series_mean(centred), 0.0, 1e-15);
}

TEST(GaussMarkov1, RecoversCorrelationTimeAndVariance) {
  // GM1 with tau = 5 s, sigma = 0.02 at 40 Hz for 10000 s (2000 correlation
  // times): the relative standard error of r(k) near the 1/e lag is about
  // sqrt(tau/T) ~ 2%, so 10% is a 4-5 sigma bound.
  const double dt = 0.025, tau = 5.0, sigma = 0.02;
  const double phi = std::exp(-dt / tau);
  const std::vector<double> x = simulate_ar({1.0, -phi}, sigma * std::sqrt(1 - phi * phi), 400000, 7);
  double bias = 0.0;
  const auto centred = remove_mean(x, bias);
  const auto acf = autocorrelation(centred, 2000, AcfScale::Biased);
  const GaussMarkov1 gm = fit_gauss_markov1(acf, dt);
  ASSERT_TRUE(gm.crossed);
  EXPECT_NEAR(gm.tau_s, tau, 0.10 * tau);
  EXPECT_NEAR(gm.variance, sigma * sigma, 0.10 * sigma * sigma);
  EXPECT_NEAR(gm.autocorrelation(gm.tau_s), gm.variance / std::exp(1.0), 1e-15);
  EXPECT_NEAR(gm.driving_variance(dt), gm.variance * (1 - gm.phi(dt) * gm.phi(dt)), 1e-18);
}

TEST(GaussMarkov1, RandomWalkNeverCrossesAndSaysSo) {
  std::vector<double> acf(100);
  for (std::size_t k = 0; k < acf.size(); ++k) acf[k] = 1.0 - 0.001 * static_cast<double>(k);
  const GaussMarkov1 gm = fit_gauss_markov1(acf, 0.025);
  EXPECT_FALSE(gm.crossed);
  EXPECT_TRUE(std::isinf(gm.tau_s));
}

TEST(ArModelImplied, Ar2AutocorrelationMatchesClosedForm) {
  // x(n) = 1.6 x(n-1) - 0.9 x(n-2) + e, var(e) = 1:
  // r0 = (1 + a2) / ((1 - a2)((1 + a2)^2 - a1^2)), r1 = -a1 r0 / (1 + a2).
  const ArModel m{{1.0, -1.6, 0.9}, 1.0};
  const auto r = ar_autocorrelation(m, 50);
  ASSERT_EQ(r.size(), 51u);
  const double r0 = 1.9 / (0.1 * (1.9 * 1.9 - 1.6 * 1.6));
  EXPECT_NEAR(r[0], r0, 1e-12 * r0);
  EXPECT_NEAR(r[1], 1.6 * r0 / 1.9, 1e-12 * r0);
  EXPECT_NEAR(r[20], 1.6 * r[19] - 0.9 * r[18], 1e-12 * r0);
  EXPECT_TRUE(ar_is_stable(m));
  EXPECT_FALSE(ar_is_stable(ArModel{{1.0, -1.01}, 1.0}));
  EXPECT_TRUE(ar_autocorrelation(ArModel{{1.0, -1.0}, 1.0}, 5).empty());  // unit root: no stationary r
}

TEST(ArModelImplied, PsdIntegratesToVariance) {
  // Parseval: the one-sided PSD over [0, fs/2] integrates to r(0).
  const ArModel m{{1.0, -1.6, 0.9}, 1.0};
  const double fs = 40.0;
  const int steps = 200000;  // trapezoid; the resonance (|pole| 0.95) spans ~300 steps
  double sum = 0.0;
  for (int i = 0; i <= steps; ++i) {
    const double f = 0.5 * fs * i / steps;
    sum += (i == 0 || i == steps ? 0.5 : 1.0) * ar_psd_one_sided(m, f, fs);
  }
  sum *= 0.5 * fs / steps;
  const double r0 = ar_autocorrelation(m, 0)[0];
  EXPECT_NEAR(sum, r0, 1e-6 * r0);
}

TEST(ArModelImplied, BurgOnLongSeriesRecoversGeneratingModel) {
  // 200000 samples: coefficient standard error ~ 1/sqrt(N) ~ 0.002, so 0.01.
  const std::vector<double> a{1.0, -0.9, 0.3, 0.2, -0.15};
  const auto x = simulate_ar(a, 0.5, 200000, 3);
  const auto models = ar_burg(x, 10);
  ASSERT_EQ(models.size(), 10u);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(models[3].a[i], a[i], 0.01) << i;
  EXPECT_NEAR(models[3].variance, 0.25, 0.01 * 0.25 * 3);  // var of the variance estimate ~ 2/N
  for (const auto& m : models) EXPECT_TRUE(ar_is_stable(m));
  // BIC (consistent) picks the true order 4; FPE/AIC may over-fit but never under-fit here.
  const SelectedOrders s = select_orders(models, x.size());
  EXPECT_EQ(s.bic, 4u);
  EXPECT_GE(s.aic, 4u);
  EXPECT_GE(s.fpe, 4u);
}

TEST(OrderCriteria, Formulas) {
  const OrderCriteria c = order_criteria(2.0, 3, 1000);
  EXPECT_DOUBLE_EQ(c.fpe, 2.0 * 1004.0 / 996.0);
  EXPECT_DOUBLE_EQ(c.aic, 1000.0 * std::log(2.0) + 6.0);
  EXPECT_DOUBLE_EQ(c.bic, 1000.0 * std::log(2.0) + 3.0 * std::log(1000.0));
}

}  // namespace
