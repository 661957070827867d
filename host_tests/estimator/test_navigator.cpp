// The whole navigation unit (alignment, INS, EKF, GNSS fusion) on analytic flights.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <numbers>
#include <random>
#include <cstdlib>

#include "estimator/earth/geomagnetic_model.hpp"
#include "estimator/ekf/aiding/declination/declination.hpp"
#include "host_tests/estimator/navigator_run.hpp"

namespace sinu::test {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

std::vector<est::ImuSample> imu_of(const std::vector<TruthSample>& truth) {
  std::vector<est::ImuSample> imu;
  imu.reserve(truth.size());
  for (const auto& s : truth) imu.push_back(s.imu);
  return imu;
}

/// The flight's IMU with a magnetometer in every sample: the Earth field
/// field_n turned into the body plus a hard iron, white noise on the field and
/// on the gyros (seeded: the same samples every run).
std::vector<est::ImuSample> imu_with_magnetometer(const std::vector<TruthSample>& truth, const Eigen::Vector3d& field_n,
                                                  const Eigen::Vector3d& hard_iron_uT, double mag_noise_uT,
                                                  double gyro_noise_rad_s, unsigned seed) {
  std::vector<est::ImuSample> imu = imu_of(truth);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01;
  for (std::size_t i = 0; i < imu.size(); ++i) {
    imu[i].has_mag = true;
    imu[i].mag_b_uT = truth[i].nav.C_nb().transpose() * field_n + hard_iron_uT;
    for (Eigen::Index k = 0; k < 3; ++k) {
      imu[i].mag_b_uT(k) += mag_noise_uT * n01(rng);
      imu[i].angular_rate_b_rad_s(k) += gyro_noise_rad_s * n01(rng);
    }
  }
  return imu;
}

TEST(Navigator, PerfectImuAndGpsThirtyMinuteFlight) {
  const auto truth = AnalyticFlight(FlightProfile{}).sample(40.0, 1860.0);
  const auto gnss = AnalyticFlight::gnss(truth, 8, 0.05, Eigen::Vector3d::Zero(), 0.5, 0.1);
  est::NavigatorConfig cfg;
  cfg.gps_latency_s = 0.05;
  const ScoredRun run(cfg, truth, 40.0, imu_of(truth), gnss);
  const RunStats& stats = run.stats;
  const est::Navigator& nav = run.nav;
  ASSERT_TRUE(nav.aligned());
  // Alignment completes during the run-up (course at 3 m/s); the 30 minutes
  // of flight are scored from 60 s after it (heading converges on the first turns).
  const double from = stats.align_t + 60.0;
  const double pos_rms = std::hypot(rms_after(stats.t, stats.pos_err_h, from), rms_after(stats.t, stats.pos_err_v, from));
  const double att_rms_deg = rms_after(stats.t, stats.att_err, from) * kRadToDeg;
  std::printf("aligned at +%.1f s; position RMS %.4f m, attitude RMS %.5f deg, rejected %zu\n",
              stats.align_t - truth.front().nav.t_s, pos_rms, att_rms_deg, stats.rejected);
  // The requirement: under 0.5 m and 0.05 deg.
  EXPECT_LT(pos_rms, 0.5);
  EXPECT_LT(att_rms_deg, 0.05);
  EXPECT_EQ(stats.rejected, 0u);
}

// The magnetometer through turns, climbs and speed changes, with the Earth
// field and the hard iron as states and the declination not given: the
// heading at rest comes from the field (off by the declination, sigma 20 deg),
// the run-up corrects it by some 11 deg, and then the field states must not
// pull the attitude away. Before the field error was made invariant (and
// turned with such a correction) a 0.4 uT magnetometer on perfect inertial
// sensors gave 1-4 deg attitude errors in the first turns.
// The field: a made-up one (pointing up in the northern hemisphere, no site's
// field), with the World Magnetic Model switched off, as the user does for a
// field the model cannot know; or the site's field as the model gives it, bent
// by a hard iron so the alignment does not recognise it: the model's strength
// and dip then start the field states (aiding/field_model) and the offset goes
// to the hard iron.
struct MagCase {
  double mag_noise_uT, gyro_noise_rad_s;
  Eigen::Vector3d hard_iron_uT;
  double max_att_rms_deg;
  bool site_field = false;  // the model's field at the site, the model on
};
class MagnetometerThroughTurns : public ::testing::TestWithParam<MagCase> {};

TEST_P(MagnetometerThroughTurns, KeepsTheAttitude) {
  const MagCase c = GetParam();
  const auto truth = AnalyticFlight(FlightProfile{}).sample(40.0, 900.0);
  const auto gnss = AnalyticFlight::gnss(truth, 8, 0.0, Eigen::Vector3d::Zero(), 0.5, 0.1);
  // Without a date the alignment evaluates the model at the middle of its span.
  const double year = 0.5 * (est::geomag::kValidFromYear + est::geomag::kValidUntilYear);
  const est::NavState& start = truth.front().nav;
  const Eigen::Vector3d field_n =
      c.site_field ? est::geomag::geomagnetic_field(start.lat_rad, start.lon_rad, start.h_m, year).b_n_uT
                   : Eigen::Vector3d(19.0, -3.6, -45.6);  // uT; declination -10.7 deg
  const std::vector<est::ImuSample> imu =
      imu_with_magnetometer(truth, field_n, c.hard_iron_uT, c.mag_noise_uT, c.gyro_noise_rad_s, 7);
  est::NavigatorConfig cfg;
  cfg.mag_sigma_uT = std::max(0.1, c.mag_noise_uT);
  cfg.alignment.use_geomagnetic_model = c.site_field;
  const ScoredRun run(cfg, truth, 40.0, imu, gnss);
  const RunStats& stats = run.stats;
  const est::Navigator& nav = run.nav;
  ASSERT_TRUE(nav.aligned());
  ASSERT_TRUE(nav.filter().layout().has(est::Effect::MagEarthField));
  const double from = stats.align_t + 120.0;  // the run-up and the first turn have found the heading
  const double att_rms_deg = rms_after(stats.t, stats.att_err, from) * kRadToDeg;
  std::printf("attitude RMS %.4f deg, magnetometer accepted %llu rejected %llu\n", att_rms_deg,
              static_cast<unsigned long long>(nav.counters().accepted[2]),
              static_cast<unsigned long long>(nav.counters().rejected[2]));
  EXPECT_LT(att_rms_deg, c.max_att_rms_deg);
  EXPECT_LT(nav.counters().rejected[2], nav.counters().accepted[2] / 100) << "the field stays consistent";
}

// Limits: perfect sensors: GNSS alone reaches 0.002 deg here (PerfectImuAndGps...),
// the field must add nothing (measured 0.0013). With noise the filter's own
// attitude sigma, from its default gyro model, is ~0.2 deg: 0.5 deg is 2.5 sigma.
INSTANTIATE_TEST_SUITE_P(Cases, MagnetometerThroughTurns,
                         ::testing::Values(MagCase{0.0, 0.0, Eigen::Vector3d::Zero(), 0.01},
                                           MagCase{0.4, 0.0, Eigen::Vector3d::Zero(), 0.5},
                                           MagCase{0.4, 1.6e-3, Eigen::Vector3d::Zero(), 0.5},
                                           MagCase{0.4, 1.6e-3, Eigen::Vector3d(15.0, -10.0, 8.0), 0.5},
                                           MagCase{0.4, 1.6e-3, Eigen::Vector3d(15.0, -10.0, 8.0), 0.5, true},
                                           MagCase{0.0, 0.0, Eigen::Vector3d(15.0, -10.0, 8.0), 0.01, true}));

/// Two minutes standing still at the analytic flight's site, GNSS every
/// epoch, and the World Magnetic Model's field there (without a date the
/// alignment evaluates the model at the middle of its span).
struct TwoMinutesAtRest {
  std::vector<TruthSample> truth;
  std::vector<est::GnssObservation> gnss;
  Eigen::Vector3d field_n;
  TwoMinutesAtRest() {
    FlightProfile still;
    still.stationary = true;
    truth = AnalyticFlight(still).sample(40.0, 120.0);
    gnss = AnalyticFlight::gnss(truth, 8, 0.0, Eigen::Vector3d::Zero(), 0.5, 0.1);
    const double year = 0.5 * (est::geomag::kValidFromYear + est::geomag::kValidUntilYear);
    const est::NavState& start = truth.front().nav;
    field_n = est::geomag::geomagnetic_field(start.lat_rad, start.lon_rad, start.h_m, year).b_n_uT;
  }
};

// A unit at rest with its magnetometer (the site's field, 0.4 uT noise, noisy
// gyros) for two minutes before take-off: nothing tells the Earth field from
// the hard iron but a rotation, so only their sum is seen. Started from the
// first sample with the hard iron's 30-uT prior, the two wandered apart along
// that direction at every small attitude correction: after 120 s the field's
// strength was 13 uT (of 51.6) and the hard iron 35 uT in z. The model's
// strength and down component held those (49.5 uT, hard iron z -1.7 uT), but
// the field still turned towards the vertical at that strength, its
// horizontal part from 20.6 to 0 uT, the hard iron taking 17 uT in x, y
// (at take-off on uav_log171 the same swap sent the field's north component
// from 23 to -8 uT). The model's inclination instead of its down component
// (aiding/field_model) holds the direction too.
TEST(Navigator, AtRestTheFieldAndTheHardIronHold) {
  const TwoMinutesAtRest rest;
  const auto& [truth, gnss, field_n] = rest;
  for (const bool soft_iron : {false, true}) {
    const std::vector<est::ImuSample> imu =
        imu_with_magnetometer(truth, field_n, Eigen::Vector3d::Zero(), 0.4, 1.6e-3, 11);
    est::NavigatorConfig cfg;
    if (soft_iron) cfg.effects.add(est::Effect::MagSoftIron);
    const ScoredRun run(cfg, truth, 40.0, imu, gnss);
    const est::Navigator& nav = run.nav;
    ASSERT_TRUE(nav.aligned());
    const Eigen::Vector3d h = nav.filter().mag_hard_iron_b_uT(), F = nav.filter().mag_earth_field_n_uT();
    std::printf("soft iron %d: hard iron [%.2f %.2f %.2f] uT, field strength %.2f uT (true %.2f)\n", soft_iron, h.x(),
                h.y(), h.z(), F.norm(), field_n.norm());
    // At rest nothing measures the strength but its prior (5 uT, the
    // magnetometer's scale error): the strength, and the vertical hard iron
    // that trades against it, within that sigma (measured 3.6 and 1.9 uT off,
    // hard iron z 3.1 and 1.2 uT; 38 uT off without the priors). The
    // horizontal hard iron (true 0) at twice the worst measured (2.1 uT),
    // a quarter of the 17 uT with the down component instead of the inclination.
    EXPECT_NEAR(F.norm(), field_n.norm(), 5.0) << "soft iron " << soft_iron;
    EXPECT_LT(std::abs(h.z()), 5.0) << "soft iron " << soft_iron;
    EXPECT_LT(h.head<2>().norm(), 4.0) << "soft iron " << soft_iron;
  }
}

// At rest nothing measures the declination (the field's direction): its prior,
// fused when the field states start (2 deg, declination_sigma_rad), should
// still be there at take-off. With the heading frozen at rest (the yaw is
// frozen while it is uncertain and unobservable, yaw_freeze_sigma_rad), every
// magnetometer update turned the field instead of the heading: after 120 s
// the declination's sigma was 3.3-3.5 deg on three seeds (on uav_log171,
// 2.0 -> 3.0 deg in 30 s). With the magnetometer holding the heading, no
// freeze: 2.8-3.0 deg, the rest the walk along the field and hard iron pair
// that only a rotation separates (docs/experiments.md).
TEST(Navigator, AtRestTheDeclinationPriorIsNotFrozenAway) {
  const TwoMinutesAtRest rest;
  const auto& [truth, gnss, field_n] = rest;
  for (const unsigned seed : {13u, 14u, 15u}) {
    const std::vector<est::ImuSample> imu =
        imu_with_magnetometer(truth, field_n, Eigen::Vector3d(2.0, -1.5, 1.0), 0.4, 1.6e-3, seed);
    const est::NavigatorConfig cfg;
    const ScoredRun run(cfg, truth, 40.0, imu, gnss);
    const est::ErrorStateFilter& filter = run.nav.filter();
    ASSERT_TRUE(filter.layout().has(est::Effect::MagEarthField));
    const est::Measurement d = est::declination_measurement(filter, 0.0, 1.0, 1e9);
    const double sigma_deg = std::sqrt((d.H * filter.P() * d.H.transpose())(0, 0)) * kRadToDeg;
    const Eigen::Vector3d F = filter.mag_earth_field_n_uT();
    const double error_deg = std::remainder(std::atan2(F.y(), F.x()) - std::atan2(field_n.y(), field_n.x()),
                                            2.0 * std::numbers::pi) * kRadToDeg;
    std::printf("seed %u: declination sigma %.3f deg (prior %.3f), error %.3f deg\n", seed, sigma_deg,
                cfg.declination_sigma_rad * kRadToDeg, error_deg);
    // 3.15 deg: between the worst measured without the freeze (3.00) and the
    // best with it (3.30).
    EXPECT_LT(sigma_deg, 3.15) << "seed " << seed;
    EXPECT_LT(std::abs(error_deg), 3.0 * sigma_deg) << "seed " << seed;
  }
}

// A magnetic heading is the angle of the horizontal field, so a field error
// (hard iron the calibration left, a local anomaly) turns it by that error over
// the horizontal field: 1 uT is 2 deg at 30 uT, but 17 deg at 84 N 60 W, where
// the horizontal field is 3.3 uT of 56. The heading's sigma was a fixed 2.9 deg
// at every site: on `sinu simulate flight --site 84,-60,100` the heading stood
// 9-12 deg off (3-4 sigma) until take-off. Here 0.5 uT of unknown hard iron
// across the field, at rest with dated fixes (the model's declination), at the
// pole's edge and at the analytic flight's site (40 N: 21 uT horizontal).
TEST(Navigator, NearAMagneticPoleTheMagneticHeadingClaimsNoMoreThanTheFieldGives) {
  constexpr double kYear = 2026.0;
  for (const double lat_deg : {84.0, 40.0}) {
    FlightProfile still;
    still.stationary = true;
    still.lat0_deg = lat_deg;
    still.lon0_deg = lat_deg > 60.0 ? -60.0 : -105.0;
    const auto truth = AnalyticFlight(still).sample(40.0, 20.0);
    auto gnss = AnalyticFlight::gnss(truth, 8, 0.0, Eigen::Vector3d::Zero(), 0.5, 0.1);
    for (est::GnssObservation& z : gnss) z.decimal_year = kYear;
    const est::NavState& start = truth.front().nav;
    const Eigen::Vector3d field_n = est::geomag::geomagnetic_field(start.lat_rad, start.lon_rad, start.h_m, kYear).b_n_uT;
    // 0.5 uT across the horizontal field: the heading's largest error for it.
    const Eigen::Vector3d across_n = Eigen::Vector3d(-field_n.y(), field_n.x(), 0.0).normalized() * 0.5;
    const Eigen::Vector3d hard_iron_b = start.C_nb().transpose() * across_n;
    const std::vector<est::ImuSample> imu = imu_with_magnetometer(truth, field_n, hard_iron_b, 0.0, 0.0, 5);
    const est::NavigatorConfig cfg;
    const ScoredRun run(cfg, truth, 40.0, imu, gnss);
    ASSERT_TRUE(run.nav.aligned());
    const double error = run.stats.att_err.front(), sigma = run.nav.alignment_result().att_sigma_rad.z();
    const double horizontal = field_n.head<2>().norm();
    std::printf("lat %.0f: horizontal field %.1f uT, heading error %.2f deg, sigma %.2f deg\n", lat_deg, horizontal,
                error * kRadToDeg, sigma * kRadToDeg);
    // The error is atan(0.5 / horizontal): 8.6 deg at 84 N, 1.4 deg at 40 N.
    // Within 1 sigma: the sigma is for a 1-uT residual (twice this one); 2.9
    // deg at 84 N was 3 sigma. At 40 N the sigma stays the declination's 2.9
    // deg (mag_heading_sigma_rad): the field term (2.7 deg) must not widen it.
    EXPECT_NEAR(error, std::atan(0.5 / horizontal), 0.2 / kRadToDeg) << "lat " << lat_deg;
    EXPECT_LT(error, sigma) << "lat " << lat_deg;
    if (lat_deg < 60.0) {
      EXPECT_NEAR(sigma, cfg.alignment.mag_heading_sigma_rad, 1e-9);
    }
  }
}

TEST(Navigator, CovarianceStaysExactlySymmetricAndPositiveDefinite) {
  const auto truth = AnalyticFlight(FlightProfile{}).sample(40.0, 400.0);
  const auto gnss = AnalyticFlight::gnss(truth, 8, 0.0, Eigen::Vector3d::Zero(), 0.5, 0.1);
  for (const auto kind : {est::NoiseModelKind::GaussMarkov, est::NoiseModelKind::AutoRegressive}) {
    est::NavigatorConfig cfg;
    cfg.noise = est::SensorNoise::defaults(kind);
    for (std::size_t e = 0; e < est::kEffectCount; ++e) cfg.effects.add(static_cast<est::Effect>(e));
    est::Navigator nav;
    nav.init(cfg, nullptr, nullptr);
    feed(nav, imu_of(truth), gnss);
    const est::StateMat& P = nav.filter().P();
    EXPECT_EQ(nav.counters().rejected[0] + nav.counters().rejected[1], 0u);
    EXPECT_GT(nav.counters().accepted[0], gnss.size() * 8 / 10) << "all epochs after alignment fused";
    EXPECT_TRUE((P - P.transpose()).cwiseAbs().maxCoeff() == 0.0) << "P must be exactly symmetric";
    Eigen::LLT<est::StateMat> llt(P);
    EXPECT_EQ(llt.info(), Eigen::Success) << "P must be positive definite";
  }
}

TEST(Navigator, GateRejectsAnOutlierAndCountsIt) {
  const auto truth = AnalyticFlight(FlightProfile{}).sample(40.0, 300.0);
  auto gnss = AnalyticFlight::gnss(truth, 8, 0.0, Eigen::Vector3d::Zero(), 0.5, 0.1);
  const std::size_t bad = gnss.size() - 100;
  gnss[bad].lat_rad += 50.0 / 6.37e6;  // 50 m north: 100 sigma
  const double t_bad = gnss[bad].arrival_s;
  est::NavigatorConfig cfg;
  const ScoredRun run(cfg, truth, 40.0, imu_of(truth), gnss);
  const RunStats& stats = run.stats;
  const est::Navigator& nav = run.nav;
  EXPECT_EQ(nav.counters().rejected[static_cast<std::size_t>(est::AidingSource::GnssPosition)], 1u);
  // The solution right after the outlier is unaffected (below 0.5 m, where
  // a fused 50 m jump would have moved it by metres).
  for (std::size_t i = 0; i < stats.t.size(); ++i) {
    if (stats.t[i] >= t_bad && stats.t[i] < t_bad + 1.0) {
      EXPECT_LT(stats.pos_err_h[i], 0.5);
    }
  }
}

}  // namespace
}  // namespace sinu::test

namespace sinu::test {
namespace {

// Chi-square 2.5% and 97.5% quantiles (scipy.stats.chi2.ppf) for 3 and 9 dof.
constexpr double kChi2Lo3 = 0.2158, kChi2Hi3 = 9.3484;
constexpr double kChi2Lo9 = 2.7004, kChi2Hi9 = 19.0228;

double fraction_inside(const std::vector<double>& x, const std::vector<double>* t, double t_from, double lo, double hi) {
  std::size_t n = 0, in = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (t && (*t)[i] < t_from) continue;
    ++n;
    if (x[i] >= lo && x[i] <= hi) ++in;
  }
  return n ? static_cast<double>(in) / static_cast<double>(n) : 0.0;
}

// Sensors drawn from exactly the filter's default model: GM bias (stationary
// start) plus white noise per axis; GNSS white noise at its declared sigma.
TEST(Navigator, NeesAndNisInsideTheirChiSquareBoundsWithAMatchedModel) {
  constexpr double kRate = 40.0;
  auto truth = AnalyticFlight(FlightProfile{}).sample(kRate, 1200.0);
  const est::SensorNoise model = est::SensorNoise::defaults(est::NoiseModelKind::GaussMarkov);
  std::mt19937_64 rng(42);
  std::normal_distribution<double> n01;
  std::array<double, 6> bias{};
  for (std::size_t a = 0; a < 6; ++a) bias[a] = std::sqrt(model.gm[a].variance) * n01(rng);
  std::vector<est::ImuSample> imu;
  imu.reserve(truth.size());
  const double dt = 1.0 / kRate;
  for (const auto& s : truth) {
    est::ImuSample m = s.imu;
    for (Eigen::Index i = 0; i < 3; ++i) {
      const auto ka = static_cast<std::size_t>(i), kg = static_cast<std::size_t>(i + 3);
      m.specific_force_b_m_s2(i) += bias[ka] + model.accel_white_m_s2_rthz * std::sqrt(kRate) * n01(rng);
      m.angular_rate_b_rad_s(i) += bias[kg] + model.gyro_white_rad_s_rthz * std::sqrt(kRate) * n01(rng);
    }
    for (std::size_t a = 0; a < 6; ++a) {
      const double phi = std::exp(-dt / model.gm[a].tau_s);
      bias[a] = phi * bias[a] + std::sqrt(model.gm[a].variance * (1.0 - phi * phi)) * n01(rng);
    }
    imu.push_back(m);
  }
  constexpr double kSigP = 0.5, kSigV = 0.1;
  auto gnss = AnalyticFlight::gnss(truth, 8, 0.0, Eigen::Vector3d::Zero(), kSigP, kSigV);
  for (auto& z : gnss) {
    z.lat_rad += kSigP * n01(rng) / 6.37e6;
    z.lon_rad += kSigP * n01(rng) / (6.37e6 * std::cos(z.lat_rad));
    z.h_m += kSigP * n01(rng);
    const double ve = n01(rng), vn = n01(rng);  // east first: x86-64 GCC's order of the former unsequenced arguments
    z.v_ne_m_s += kSigV * Eigen::Vector2d(vn, ve);
  }
  est::NavigatorConfig cfg;
  cfg.noise = model;
  const ScoredRun run(cfg, truth, kRate, imu, gnss);
  const RunStats& stats = run.stats;
  // Scored from 60 s after alignment: the coarse heading prior is not Gaussian.
  const double from = stats.align_t + 60.0;
  const double nees_in = fraction_inside(stats.nees, &stats.t, from, kChi2Lo9, kChi2Hi9);
  const double nis_in = fraction_inside(stats.nis_pos, nullptr, 0.0, kChi2Lo3, kChi2Hi3);
  double mean_nees = 0.0;
  for (double v : stats.nees) mean_nees += v / static_cast<double>(stats.nees.size());
  std::printf("NEES inside 95%% bounds %.3f (mean %.2f, 9 dof); NIS inside %.3f; rejected %zu\n", nees_in, mean_nees,
              nis_in, stats.rejected);
  // The requirement: inside the two-sided 95% bounds at least 90% of the time.
  EXPECT_GE(nees_in, 0.90);
  EXPECT_GE(nis_in, 0.90);
}

}  // namespace
}  // namespace sinu::test

namespace sinu::test {
namespace {

struct ReceiverRun {
  double pos_h_rms_m = 0.0;
  std::size_t rejected = 0, epochs = 0;
  Eigen::Vector2d white_scale;
};

/// A receiver whose position error is white (sigma white_m) plus a 120-s
/// Gauss-Markov process (sigma gm_m) per axis, and which states the total,
/// sqrt(white^2 + gm^2), as GST would; the IMU perfect. Scored from 120 s
/// after the alignment.
ReceiverRun run_receiver(double white_m, double gm_m, bool learn_split) {
  constexpr double kRate = 40.0, kFixPeriod = 0.2;
  const auto truth = AnalyticFlight(FlightProfile{}).sample(kRate, 900.0);
  const double stated = std::hypot(white_m, gm_m);
  auto gnss = AnalyticFlight::gnss(truth, 8, 0.0, Eigen::Vector3d::Zero(), stated, 0.1);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  const double phi = std::exp(-kFixPeriod / 120.0);
  Eigen::Vector3d gm(gm_m * n01(rng), gm_m * n01(rng), gm_m * n01(rng));
  for (auto& z : gnss) {
    Eigen::Vector3d e;
    for (Eigen::Index i = 0; i < 3; ++i) {
      gm(i) = phi * gm(i) + gm_m * std::sqrt(1.0 - phi * phi) * n01(rng);
      e(i) = gm(i) + white_m * n01(rng);
    }
    z.lat_rad += e.x() / 6.37e6;
    z.lon_rad += e.y() / (6.37e6 * std::cos(z.lat_rad));
    z.h_m -= e.z();
  }
  est::NavigatorConfig cfg;
  cfg.effects.add(est::Effect::GpsPositionBias);
  cfg.gnss_white_scale.enabled = learn_split;
  const ScoredRun run(cfg, truth, kRate, imu_of(truth), gnss);
  EXPECT_TRUE(run.nav.aligned());
  return {rms_after(run.stats.t, run.stats.pos_err_h, run.stats.align_t + 120.0), run.stats.rejected, gnss.size(),
          run.nav.gnss_white_scale()};
}

// The split of a receiver's stated error into white and correlated is a guess
// (90 % correlated, as this project's simulator and u-blox receivers behave).
// A receiver whose error is all white, stating it honestly (an independent
// simulator's), made the filter expect a third of its real scatter: thousands
// of epochs rejected, vertical-velocity resets, 2.7 m against the receiver's
// 2.8 m. The white part's factor is learnt from the innovations.
TEST(Navigator, AWhiteReceiverStatingItsErrorHonestlyIsLearntNotRejected) {
  const ReceiverRun learnt = run_receiver(2.0, 0.0, true);
  const ReceiverRun fixed = run_receiver(2.0, 0.0, false);
  std::printf("white 2 m: learnt %.3f m, %zu of %zu rejected, scale %.2f / %.2f; fixed split %.3f m, %zu rejected\n",
              learnt.pos_h_rms_m, learnt.rejected, learnt.epochs, learnt.white_scale.x(), learnt.white_scale.y(),
              fixed.pos_h_rms_m, fixed.rejected);
  // All of the stated variance is white: the factor at its cap sqrt(1 / 0.1),
  // within the estimate's scatter over a 60-s memory (~300 fixes: 5 %).
  EXPECT_NEAR(learnt.white_scale.x(), std::sqrt(10.0), 0.1 * std::sqrt(10.0));
  EXPECT_NEAR(learnt.white_scale.y(), std::sqrt(10.0), 0.1 * std::sqrt(10.0));
  // A 2-sigma gate on a consistent filter would pass 95 %; a few of 4500 out is
  // the alignment's first seconds.
  EXPECT_LT(learnt.rejected, learnt.epochs / 100);
  // A perfect IMU averages white fixes over many epochs: well under the fix's 2 m.
  EXPECT_LT(learnt.pos_h_rms_m, 0.5);
  // And the learning is what does it (the fixed split rejects and follows the fixes).
  EXPECT_GT(fixed.rejected, 10 * std::max<std::size_t>(learnt.rejected, 1));
}

// A receiver as the split assumes (GM 0.95 sigma, white 0.32 sigma) keeps the
// factor near 1: the learning leaves a receiver that fits alone.
TEST(Navigator, AReceiverAsTheSplitAssumesKeepsItsFactorNearOne) {
  const ReceiverRun r = run_receiver(0.4, 1.2, true);
  std::printf("white 0.4 m + GM 1.2 m: %.3f m, %zu rejected, scale %.2f / %.2f\n", r.pos_h_rms_m, r.rejected,
              r.white_scale.x(), r.white_scale.y());
  // 1 is the floor; the innovations of 300 fixes scatter the variance by ~8 %.
  EXPECT_LT(r.white_scale.x(), 1.15);
  EXPECT_LT(r.white_scale.y(), 1.15);
  EXPECT_LT(r.rejected, r.epochs / 100);
}

}  // namespace
}  // namespace sinu::test
