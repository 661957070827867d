// The calibration glue: the wavelet denoiser adapter (length and time
// alignment) and the plain-language findings on series with known structure.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "firmware/host/calibration/axis_calibration.hpp"
#include "firmware/host/calibration/calibration_run.hpp"
#include "firmware/host/calibration/denoiser.hpp"

namespace {

using namespace sinu::calibration;

TEST(DenoiserAdapter, KeepsLengthAndRemovesTheFilterDelay) {
  Denoiser d;
  std::string why;
  ASSERT_TRUE(make_wavelet_denoiser("db4", 3, d, why)) << why;
  // A 0.2 Hz sine at 40 Hz is far inside the 2.5 Hz pass band: after the
  // delay is removed it must come back in phase (no shift of even one sample).
  std::vector<double> x(8000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::sin(2 * std::numbers::pi * 0.2 * static_cast<double>(i) / 40.0);
  const auto y = d.apply(x, 40.0);
  ASSERT_EQ(y.size(), x.size());
  double err = 0.0;
  for (std::size_t i = 200; i + 200 < x.size(); ++i) err = std::max(err, std::abs(y[i] - x[i]));
  // A one-sample shift would leave an error of 2 pi 0.2/40 = 0.031; the
  // pass-band ripple of the level-3 approximation at 0.2 Hz is ~1e-3.
  EXPECT_LT(err, 0.01);
  EXPECT_FALSE(make_wavelet_denoiser("sym8", 3, d, why));
  EXPECT_NE(why.find("sym8"), std::string::npos);
  EXPECT_FALSE(make_wavelet_denoiser("db4", 0, d, why));
}

TEST(Findings, NamePeriodicComponentAndNothingForWhiteGm) {
  // Periodic-random (resonator with 20 s period) plus white noise at 40 Hz.
  const double dt = 0.025, period = 20.0, r = std::exp(-0.02 * 2 * std::numbers::pi / period * dt);
  const double w = 2 * std::numbers::pi / period * dt;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<double> x(200000);
  double p1 = 0.0, p2 = 0.0;
  for (double& v : x) {
    const double p = 2 * r * std::cos(w) * p1 - r * r * p2 + 1e-3 * n(rng);
    p2 = p1;
    p1 = p;
    v = p;
  }
  AxisOptions opt;
  opt.dt_s = dt;
  opt.acf_max_lag_s = 120.0;
  const AxisCalibration c = calibrate_axis("gx", x, x, opt);
  bool periodic = false;
  for (const auto& f : findings(c, dt)) {
    if (f.find("GM1 misses the periodic component near") != std::string::npos) {
      periodic = true;
      const double said = std::stod(f.substr(f.find("near ") + 5));
      EXPECT_NEAR(said, period, 0.1 * period) << f;  // period read from the crest, 10%
    }
  }
  EXPECT_TRUE(periodic);

  // A plain GM1 process (tau 2 s): no periodic claim, GM1 decays.
  std::vector<double> g(200000);
  const double phi = std::exp(-dt / 2.0);
  double s = 0.0;
  for (double& v : g) v = s = phi * s + n(rng);
  const AxisCalibration cg = calibrate_axis("ax", g, g, opt);
  EXPECT_TRUE(cg.gm.crossed);
  EXPECT_NEAR(cg.gm.tau_s, 2.0, 0.3);  // 10^5 samples / 80 correlation times: ~5% std
  for (const auto& f : findings(cg, dt)) EXPECT_EQ(f.find("misses the periodic component"), std::string::npos) << f;
}

}  // namespace
