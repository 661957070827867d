// The innovations' whiteness that diagnose reports before and after: the
// lag-1 autocorrelation of the normalised innovations, per aiding source,
// against sequences whose autocorrelation is known.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "firmware/host/diagnose/innovation_stats.hpp"

namespace sinu::diagnose {
namespace {

est::InnovationRecord record(est::AidingSource source, const Eigen::Vector3d& y, const Eigen::Vector3d& sigma, int rows) {
  est::InnovationRecord r;
  r.source = source;
  r.result.rows = rows;
  r.result.innovation = y;
  r.result.innovation_sigma = sigma;
  r.result.accepted = true;
  return r;
}

TEST(InnovationStats, WhitenessIsTheLagOneAutocorrelationPerSource) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  InnovationStatsListener listener;
  const double rho = 0.9;  // the velocity's innovations: AR(1), per component
  Eigen::Vector2d ar = Eigen::Vector2d::Zero();
  const Eigen::Vector3d sigma_pos(2.0, 2.0, 4.0), sigma_vel(0.1, 0.1, 1.0);
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    // Position: white, each component at its own sigma (z is what counts).
    const Eigen::Vector3d y_pos(sigma_pos.x() * n01(rng), sigma_pos.y() * n01(rng), sigma_pos.z() * n01(rng));
    listener.on_innovation(record(est::AidingSource::GnssPosition, y_pos, sigma_pos, 3));
    for (Eigen::Index k = 0; k < 2; ++k) ar(k) = rho * ar(k) + std::sqrt(1.0 - rho * rho) * n01(rng);
    listener.on_innovation(
        record(est::AidingSource::GnssVelocity, Eigen::Vector3d(0.1 * ar(0), 0.1 * ar(1), 0.0), sigma_vel, 2));
  }
  const InnovationStats& s = listener.stats();
  // White: the estimate's standard error is 1/sqrt(3n) = 0.004; 0.02 is five of them.
  EXPECT_NEAR(s.source[0].lag1(), 0.0, 0.02);
  // AR(1) 0.9: standard error sqrt((1 - rho^2) / 2n) = 0.002; 0.02 leaves the
  // normalisation by all n terms (a 1/n bias) far inside.
  EXPECT_NEAR(s.source[1].lag1(), rho, 0.02);
  // Interleaved sources do not mix: the magnetometer saw nothing.
  EXPECT_EQ(s.source[2].count, 0u);
  EXPECT_EQ(s.source[2].lag1(), 0.0);
}

}  // namespace
}  // namespace sinu::diagnose
