// The magnetometer's heading in an in-motion alignment (field_heading_update.hpp).
// In a steady acceleration the in-motion alignment knows the attitude except
// about the specific force's axis, which leans atan(a / g) off the vertical:
// its tilt is then as uncertain as its yaw (a third simulator's fixed wing
// speeding up at 0.5 m/s^2: tilt sigma 0.1-0.3 rad for 8 s, aligned only
// after 11-14 s). The heading fixes that rotation, and the tilt with it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "estimator/align/field_heading_update.hpp"
#include "estimator/earth/geomagnetic_model.hpp"
#include "estimator/ins/rotation.hpp"
#include "host_tests/estimator/alignment_run.hpp"
#include "host_tests/estimator/navigator_run.hpp"

namespace sinu::test {
namespace {

/// phi with C_hat = (I - [phi x]) C_true, exact for any size: C_hat = R(-phi) C_true.
Eigen::Vector3d error_of(const Eigen::Quaterniond& est_q, const Eigen::Quaterniond& true_q) {
  const Eigen::AngleAxisd d(true_q * est_q.conjugate());
  return d.angle() * d.axis();
}

/// A site's field (fw2's of the third simulator: 48.3 uT, dip 63.6 deg, declination 3.4 deg).
Eigen::Vector3d field_n_uT() {
  const double F = 48.3, I = 63.6 * kDeg, D = 3.4 * kDeg;
  return F * Eigen::Vector3d(std::cos(I) * std::cos(D), std::cos(I) * std::sin(D), std::sin(I));
}

// 400 draws: the unit flies course 147.6 deg at 0.5 m/s^2; the prior is the
// in-motion alignment's as measured there (2 deg about the two
// well-determined axes, ~30 rad about the specific force's), its error along
// that axis any angle; the heading carries 3 deg of noise. The updated
// attitude's error against its covariance: NEES mean 3 for 3 dof; 400 draws
// give it +-0.12 (1 sigma), so [2.5, 3.5] is 4 sigma. The tilt sigma ends
// near the well-determined axes' 2 deg, under the alignment's 0.1 rad.
TEST(FieldHeadingUpdate, ResolvesASteadyAccelerationsAxisConsistently) {
  const Eigen::Quaterniond q_true = est::quat_from_euler(0.0, 2.0 * kDeg, 147.6 * kDeg);
  const Eigen::Vector3d track(std::cos(147.6 * kDeg), std::sin(147.6 * kDeg), 0.0);
  const Eigen::Vector3d u = (0.5 * track - Eigen::Vector3d(0.0, 0.0, 9.81)).normalized();
  const double small = 2.0 * kDeg, weak = 30.0, heading_sigma = 3.0 * kDeg;
  const Eigen::Matrix3d P0 = small * small * Eigen::Matrix3d::Identity() + weak * weak * u * u.transpose();
  const Eigen::Vector3d mag_b = q_true.conjugate() * field_n_uT();
  std::mt19937 rng(7);
  std::normal_distribution<double> n01;
  std::uniform_real_distribution<double> any_angle(-std::numbers::pi, std::numbers::pi);
  double nees = 0.0, worst_tilt_sigma = 0.0;
  constexpr int kDraws = 400;
  for (int k = 0; k < kDraws; ++k) {
    // Any turn about the weak axis after a small error (isotropic: the order does not matter).
    const Eigen::Vector3d s = small * Eigen::Vector3d(n01(rng), n01(rng), n01(rng));
    Eigen::Quaterniond q = est::quat_from_rotation_vector(-any_angle(rng) * u) * est::quat_from_rotation_vector(-s) * q_true;
    Eigen::Matrix3d P = P0;
    ASSERT_TRUE(est::update_with_field_heading(q, P, mag_b, 3.4 * kDeg + heading_sigma * n01(rng), heading_sigma));
    const Eigen::Vector3d e = error_of(q, q_true);
    nees += e.dot(P.ldlt().solve(e)) / kDraws;
    worst_tilt_sigma = std::max(worst_tilt_sigma, std::sqrt(std::max(P(0, 0), P(1, 1))));
  }
  std::printf("NEES %.3f (3 dof), worst tilt sigma %.2f deg\n", nees, worst_tilt_sigma / kDeg);
  EXPECT_GT(nees, 2.5);
  EXPECT_LT(nees, 3.5);
  EXPECT_LT(worst_tilt_sigma, 2.5 * kDeg);
}

// A prior that knows the yaw to 5 deg and a heading 60 deg away: refused
// (12 sigma), nothing changed. At a magnetic pole's horizontal field of 2 %
// of the total, no heading either.
TEST(FieldHeadingUpdate, RefusesAContradictionAndAFieldWithoutAHeading) {
  const Eigen::Quaterniond q_true = est::quat_from_euler(0.1, 0.0, 1.0);
  Eigen::Quaterniond q = q_true;
  const Eigen::Matrix3d P0 = Eigen::Vector3d(1e-4, 1e-4, std::pow(5.0 * kDeg, 2)).asDiagonal();
  Eigen::Matrix3d P = P0;
  const Eigen::Vector3d mag_b = q_true.conjugate() * field_n_uT();
  EXPECT_FALSE(est::update_with_field_heading(q, P, mag_b, 3.4 * kDeg + 60.0 * kDeg, 3.0 * kDeg));
  EXPECT_TRUE(q.isApprox(q_true));
  EXPECT_TRUE(P.isApprox(P0));
  const Eigen::Vector3d polar_b = q_true.conjugate() * Eigen::Vector3d(1.0, 0.0, 50.0);
  EXPECT_FALSE(est::update_with_field_heading(q, P, polar_b, 0.0, 3.0 * kDeg));
}

// The navigator started in the air during a straight, level speed-up at
// 1 m/s^2 (perfect IMU with a magnetometer, GNSS 10 Hz): aligned on the
// field within 4 s (the in-motion alignment's 3-s window and an epoch; the
// old rule, tilt sigma under 0.1 rad before the field's heading, waited for
// the end of the acceleration, here never), and the attitude within 1 deg
// from then on (the alignment's sigmas are ~2 deg; measured 0.05 deg).
TEST(FieldHeadingUpdate, AnInMotionStartDuringASpeedUpAlignsOnTheField) {
  const Trajectory tr = straight_level(30.0, 1.0);
  const est::NavState& start = tr.truth.front().nav;
  const double year = 0.5 * (est::geomag::kValidFromYear + est::geomag::kValidUntilYear);
  std::vector<est::ImuSample> imu;
  for (const TruthSample& s : tr.truth) {
    imu.push_back(s.imu);
    imu.back().has_mag = true;
    imu.back().mag_b_uT = s.nav.q_nb.conjugate() *
                          est::geomag::geomagnetic_field(start.lat_rad, start.lon_rad, start.h_m, year).b_n_uT;
  }
  est::NavigatorConfig cfg;
  cfg.gps_latency_s = 0.0;  // the epochs arrive at their time of validity
  const ScoredRun run(cfg, tr.truth, kImuHz, imu, tr.gnss);
  ASSERT_TRUE(run.nav.aligned());
  EXPECT_LT(run.stats.align_t - start.t_s, 4.0);
  const est::HeadingSource source = run.nav.alignment_result().heading_source;
  EXPECT_TRUE(source == est::HeadingSource::MagnetometerModelDeclination ||
              source == est::HeadingSource::MagnetometerUndatedModel);
  double worst = 0.0;
  for (const double e : run.stats.att_err) worst = std::max(worst, e);
  EXPECT_LT(worst, 1.0 * kDeg);
}

}  // namespace
}  // namespace sinu::test
