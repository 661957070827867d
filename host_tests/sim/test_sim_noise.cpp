// The stochastic processes of the IMU error model have the statistics their
// parameters promise, and the default model's periodic-random part shows the
// oscillating autocorrelation a first-order GM model cannot follow.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "firmware/host/sim/error_processes.hpp"
#include "firmware/host/sim/imu_error_model.hpp"
#include "firmware/host/sim/rng.hpp"

using namespace sinu::sim;

namespace {

double mean(const std::vector<double>& x) {
  double s = 0.0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}

// Sample autocorrelation at `lag` (normalised by the lag-0 value).
double autocorrelation(const std::vector<double>& x, std::size_t lag) {
  const double m = mean(x);
  double c0 = 0.0, c = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) c0 += (x[i] - m) * (x[i] - m);
  for (std::size_t i = 0; i + lag < x.size(); ++i) c += (x[i] - m) * (x[i + lag] - m);
  return c / c0;
}

double stddev(const std::vector<double>& x) {
  const double m = mean(x);
  double s = 0.0;
  for (double v : x) s += (v - m) * (v - m);
  return std::sqrt(s / static_cast<double>(x.size() - 1));
}

constexpr double kDt = 1.0 / 40.0;

}  // namespace

TEST(ErrorProcesses, RngIsDeterministicAndStreamsDiffer) {
  Rng a(42, RngStream::ImuNoise), b(42, RngStream::ImuNoise), c(42, RngStream::Gps);
  for (int i = 0; i < 100; ++i) {
    const auto x = a.next_u64();
    EXPECT_EQ(x, b.next_u64());
    EXPECT_NE(x, c.next_u64());
  }
  // Standard normal: 200k samples give mean within 5/sqrt(n) = 0.011 and std within 1 %.
  Rng r(1, RngStream::ImuNoise);
  std::vector<double> x(200000);
  for (double& v : x) v = r.normal();
  EXPECT_NEAR(mean(x), 0.0, 0.011);
  EXPECT_NEAR(stddev(x), 1.0, 0.01);
}

TEST(ErrorProcesses, GaussMarkovHasItsSigmaAndCorrelationTime) {
  // Many independent runs so the estimate is not dominated by a few correlation times.
  const double sigma = 2e-3, tau = 20.0;
  Rng rng(3, RngStream::ImuNoise);
  std::vector<double> x;
  for (int run = 0; run < 50; ++run) {
    GaussMarkov gm;
    gm.init(sigma, tau, kDt, rng);
    for (int k = 0; k < 40 * 400; ++k) x.push_back(gm.step(rng));
  }
  // 50 runs x 20 correlation times = 1000 independent-ish samples: std to ~3 %.
  EXPECT_NEAR(stddev(x) / sigma, 1.0, 0.1);
  // Autocorrelation at one tau is exp(-1) = 0.368.
  EXPECT_NEAR(autocorrelation(x, static_cast<std::size_t>(tau / kDt)), std::exp(-1.0), 0.06);
}

TEST(ErrorProcesses, PeriodicRandomOscillatesWithItsPeriodAndSigma) {
  const double sigma = 6e-3, period = 12.0, zeta = 0.05;
  Rng rng(4, RngStream::ImuNoise);
  PeriodicRandom p;
  p.init(sigma, period, zeta, kDt, rng);
  std::vector<double> x(40 * 20000);
  for (double& v : x) v = p.step(rng);
  // Decay time 1/(zeta w0) = 38 s: 20000 s hold ~500 of them: std to ~5 %.
  EXPECT_NEAR(stddev(x) / sigma, 1.0, 0.15);
  // Damped cosine: negative at half a period, positive at a full one, as
  // exp(-zeta w0 t) cos(w_d t) says (to the estimation noise of ~0.05).
  const double w0 = 2 * std::numbers::pi / period / std::sqrt(1 - zeta * zeta);
  for (double lag_periods : {0.5, 1.0, 1.5}) {
    const double t = lag_periods * period;
    const double expected = std::exp(-zeta * w0 * t) * std::cos(2 * std::numbers::pi * lag_periods);
    EXPECT_NEAR(autocorrelation(x, static_cast<std::size_t>(t / kDt)), expected, 0.08) << lag_periods;
  }
  // A first-order GM process is never negatively correlated: this one is.
  EXPECT_LT(autocorrelation(x, static_cast<std::size_t>(0.5 * period / kDt)), -0.3);
}

TEST(ErrorProcesses, RandomWalkVarianceGrowsLinearly) {
  const double K = 1e-5, T = 100.0;
  Rng rng(5, RngStream::ImuNoise);
  std::vector<double> end;
  for (int run = 0; run < 2000; ++run) {
    RandomWalk w;
    w.init(K, kDt);
    for (int k = 0; k < static_cast<int>(T / kDt); ++k) w.step(rng);
    end.push_back(w.value());
  }
  // var = K^2 T; 2000 runs estimate the std to ~1.6 %.
  EXPECT_NEAR(stddev(end) / (K * std::sqrt(T)), 1.0, 0.06);
}

TEST(ErrorProcesses, DefaultModelIsPeriodicDominatedAndSeedDependent) {
  Rng a(1, RngStream::ImuErrorParameters), b(2, RngStream::ImuErrorParameters);
  const ImuErrorModel m1 = draw_default_imu_error_model(a), m2 = draw_default_imu_error_model(b);
  EXPECT_NE(m1.gyro.axis[0].periodic_period_s, m2.gyro.axis[0].periodic_period_s);
  for (const TriadErrorModel* t : {&m1.accel, &m1.gyro}) {
    EXPECT_NEAR(t->quantisation_step, 2.0 * t->full_scale / 65536.0, 1e-15);  // 16 bits
    for (const AxisErrorModel& ax : t->axis) {
      EXPECT_GT(ax.periodic_sigma, ax.gm_sigma);  // the part a GM model misses dominates
      EXPECT_GE(ax.periodic_period_s, 4.0);       // seconds to a minute
      EXPECT_LE(ax.periodic_period_s, 60.0);
      EXPECT_LT(ax.periodic_damping, 0.2);        // lightly damped: several visible cycles
    }
  }
}
