// Multi-position (six-position) accelerometer calibration: the fit on exact
// means, the still-segment detector on simulated sessions, and the fit on ten
// simulated units (ten seeds) against their hidden scale factors and
// misalignments, with the Cramer-Rao bound of each session computed here from
// the unit's hidden noise model (independently of the fit's code).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>

#include "estimator/earth/wgs84.hpp"
#include "firmware/host/calibration/bench_positions.hpp"
#include "firmware/host/calibration/calibration_run.hpp"
#include "firmware/host/calibration/six_position.hpp"
#include "firmware/host/calibration/six_position_run.hpp"
#include "firmware/host/calibration/still_segments.hpp"
#include "firmware/host/sim/simulation.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace {

using namespace sinu;
using namespace sinu::calibration;
using nlohmann::json;

constexpr double kDeg = std::numbers::pi / 180.0;

Eigen::Matrix3d gain_of(const Eigen::Vector3d& scale_ppm, const Eigen::Matrix3d& M) {
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  S.diagonal() += scale_ppm * 1e-6;
  return S * (Eigen::Matrix3d::Identity() + M);
}

Eigen::Matrix3d random_off_diagonal(std::mt19937_64& rng, double max) {
  std::uniform_real_distribution<double> u(-max, max);
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (r != c) M(r, c) = u(rng);
  return M;
}

Eigen::Matrix3d random_rotation(std::mt19937_64& rng, double max_angle) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(-max_angle, max_angle);
  return Eigen::AngleAxisd(u(rng), Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized()).toRotationMatrix();
}

TEST(SymmetricForm, OfASymmetricMisalignmentIsItselfAndARotationDoesNotChangeIt) {
  std::mt19937_64 rng(5);
  Eigen::Matrix3d M = random_off_diagonal(rng, 0.015);
  M = 0.5 * (M + M.transpose()).eval();
  const Eigen::Vector3d s(12000.0, -8000.0, 3000.0);
  Eigen::Vector3d s_out;
  Eigen::Matrix3d M_out;
  symmetric_form(gain_of(s, M), s_out, M_out);
  EXPECT_LT((s_out - s).cwiseAbs().maxCoeff(), 1e-6);  // ppm: round-off only
  EXPECT_LT((M_out - M).cwiseAbs().maxCoeff(), 1e-12);
  // G R^T has the same magnitudes for every input: the same form.
  const Eigen::Matrix3d R = random_rotation(rng, 0.05);
  Eigen::Vector3d s2;
  Eigen::Matrix3d M2;
  symmetric_form(gain_of(s, M) * R.transpose(), s2, M2);
  EXPECT_LT((s2 - s).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT((M2 - M).cwiseAbs().maxCoeff(), 1e-12);
}

// Means without noise, in the positions the bench asks for, each placed a
// few degrees off and at any heading: the fit must return the unit exactly
// (in the symmetric form: the triad's rotation is not observable).
std::vector<SegmentMean> exact_means(const Eigen::Matrix3d& G, const Eigen::Vector3d& b, std::size_t positions,
                                     double g, std::mt19937_64& rng) {
  std::vector<SegmentMean> out;
  for (std::size_t k = 0; k < positions; ++k) {
    const Eigen::Vector3d up = random_rotation(rng, 3.0 * kDeg) * position_up_b(k);
    SegmentMean m;
    m.accel_m_s2 = G * (g * up) + b;
    m.accel_sigma_m_s2 = Eigen::Vector3d::Constant(1e-3);
    out.push_back(m);
  }
  return out;
}

TEST(SixPositionFit, ExactMeansGiveTheUnitBack) {
  std::mt19937_64 rng(11);
  const Eigen::Vector3d s(14000.0, -9000.0, 4000.0), b(0.08, -0.05, 0.12);
  const Eigen::Matrix3d M = random_off_diagonal(rng, 0.015);
  GravityModel gravity;
  gravity.latitude_given = gravity.height_given = true;
  gravity.latitude_deg = 47.0;
  const double g = gravity.g_m_s2();
  Eigen::Vector3d s_true;
  Eigen::Matrix3d M_true;
  symmetric_form(gain_of(s, M), s_true, M_true);

  SixPositionFit fit;
  std::string why;
  ASSERT_TRUE(fit_six_position(exact_means(gain_of(s, M), b, 14, g, rng), gravity, fit, why)) << why;
  EXPECT_TRUE(fit.misalign_fitted);
  EXPECT_EQ(fit.parameters, 9u);
  EXPECT_EQ(fit.dof, 5u);
  // Exact data: only the solver's convergence remains (1e-6 ppm, 1e-10 rad, 1e-9 m/s^2).
  EXPECT_LT((fit.accel_scale_ppm - s_true).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT((fit.accel_misalign_rad - M_true).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((fit.accel_bias_m_s2 - b).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT(fit.residual_rms_m_s2, 1e-9);

  // The six faces alone: bias and scale only, the scale then holding the
  // misalignment's second-order term |G e_i| = (1 + s_i) |(I + M) e_i| (up to
  // the few-degree placement, which mixes in first-order misalignment terms
  // of the size M x 3 deg: below 1000 ppm here).
  ASSERT_TRUE(fit_six_position(exact_means(gain_of(s, M), b, 6, g, rng), gravity, fit, why)) << why;
  EXPECT_FALSE(fit.misalign_fitted);
  EXPECT_EQ(fit.parameters, 6u);
  for (Eigen::Index i = 0; i < 3; ++i) {
    const double apparent = ((1.0 + s[i] * 1e-6) * (Eigen::Matrix3d::Identity() + M).col(i).norm() - 1.0) * 1e6;
    EXPECT_NEAR(fit.accel_scale_ppm[i], apparent, 1000.0) << i;
  }
  // Without the misalignment the six faces give the scale to the second-order term alone.
  ASSERT_TRUE(fit_six_position(exact_means(gain_of(s, Eigen::Matrix3d::Zero()), b, 6, g, rng), gravity, fit, why));
  EXPECT_LT((fit.accel_scale_ppm - s).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT((fit.accel_bias_m_s2 - b).cwiseAbs().maxCoeff(), 1e-9);

  EXPECT_FALSE(fit_six_position(exact_means(gain_of(s, M), b, 5, g, rng), gravity, fit, why));
  EXPECT_NE(why.find("at least 6"), std::string::npos) << why;
}

// ---------------------------------------------------------------------------
// Simulated units.

struct Session {
  sim::SimResult sim;
  StaticSession data;
  SessionStillParts parts;
  std::vector<SessionCalibration> noise;
  SixPositionCalibration cal;
  PositionsOutcome outcome = PositionsOutcome::Failed;
  std::string why;
};

sim::SimOptions positions_options(std::uint64_t seed, std::size_t positions, double hold_s) {
  sim::SimOptions o;
  o.mode = sim::SimMode::Static;
  o.seed = seed;
  o.positions = positions;
  o.hold_s = hold_s;
  o.unit_accel_errors = true;
  return o;
}

void simulate_and_fit(const sim::SimOptions& opt, Session& s, bool gravity_given = true) {
  test::TempDir dir;
  sim::SimOptions o = opt;
  o.out_dir = dir.path().string();
  dataset::Diagnostic err;
  ASSERT_TRUE(sim::run_simulation(o, s.sim, err)) << err.to_string();
  ASSERT_TRUE(load_static_session(o.out_dir, s.data, err)) << err.to_string();
  s.parts = find_still_parts(s.data, 0);
  const StaticSession noise = s.parts.whole ? s.data : slice_session(s.data, s.parts.noise_begin, s.parts.noise_end);
  s.noise.push_back(calibrate_session(noise, no_denoiser(), ModelChoice{}));
  GravityModel gravity;
  if (gravity_given) {
    gravity.latitude_given = gravity.height_given = true;
    gravity.latitude_deg = s.sim.hidden["site"]["lat_deg"].get<double>();
    gravity.height_m = s.sim.hidden["site"]["ground_h_m"].get<double>();
  }
  s.outcome = calibrate_positions({s.parts}, s.noise, gravity, s.cal, s.why);
}

Eigen::Vector3d vec3(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }
Eigen::Matrix3d mat3(const json& j) {
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r) m.row(r) = vec3(j[static_cast<std::size_t>(r)]).transpose();
  return m;
}

TEST(StillSegments, OnePerPositionAndNoTransition) {
  Session s;
  const double hold = 120.0;
  simulate_and_fit(positions_options(21, 14, hold), s);
  ASSERT_EQ(s.outcome, PositionsOutcome::Fitted) << s.why;
  const json& pos = s.sim.hidden["positions"];
  ASSERT_EQ(s.parts.segments.size(), 14u);
  EXPECT_EQ(s.parts.attitudes, 14u);
  for (std::size_t k = 0; k < 14; ++k) {
    const StillSegment& seg = s.parts.segments[k];
    const double from = pos[k]["still_from_t"].get<double>(), to = pos[k]["still_to_t"].get<double>();
    // Inside the hold (no sample of a turn; one sample period of slack for
    // the index-to-time rounding) and most of it: at most the trimmed second
    // and the half-second block holding the turn's start lost at each end.
    EXPECT_GE(seg.t_start_s, from - 0.025) << k;
    EXPECT_LE(seg.t_end_s, to + 0.025) << k;
    EXPECT_GT(seg.duration_s(), hold - 2.0 * (1.0 + 0.5) - 0.1) << k;
    EXPECT_EQ(attitude_name(seg.up_b()), pos[k]["name"].get<std::string>()) << k;
  }
  EXPECT_FALSE(s.parts.whole);
  // The noise models come from the longest hold, not the whole session.
  EXPECT_LT(s.noise[0].duration_s, hold);
}

TEST(StillSegments, ALevelSessionIsOneSegmentAndStaysAWholeSession) {
  Session s;
  sim::SimOptions o;
  o.mode = sim::SimMode::Static;
  o.seed = 7;
  o.duration_s = 1800.0;
  simulate_and_fit(o, s);
  EXPECT_EQ(s.outcome, PositionsOutcome::SinglePosition);
  EXPECT_EQ(s.parts.attitudes, 1u);
  EXPECT_TRUE(s.parts.whole);
  ASSERT_EQ(s.parts.segments.size(), 1u) << "a still session is one still run";
  EXPECT_EQ(s.noise[0].axes[0].samples, s.data.imu[0].size()) << "the noise models see the whole session";
}

TEST(StillSegments, TooFewFacesIsAnErrorThatNamesThem) {
  Session s;
  simulate_and_fit(positions_options(22, 6, 60.0), s);
  ASSERT_EQ(s.outcome, PositionsOutcome::Fitted) << s.why;
  // The first four faces only.
  SessionStillParts four = s.parts;
  four.segments.resize(4);
  SixPositionCalibration cal;
  std::string why;
  EXPECT_EQ(calibrate_positions({four}, s.noise, GravityModel{}, cal, why), PositionsOutcome::Failed);
  EXPECT_NE(why.find("4 attitudes"), std::string::npos) << why;
  EXPECT_NE(why.find("too few faces"), std::string::npos) << why;
  EXPECT_NE(why.find("missing: -y up, +z up"), std::string::npos) << why;
}

// --- The Cramer-Rao bound of one simulated session ---------------------------
// The segment means' errors are Gaussian with a covariance known from the
// hidden noise model: white noise, Gauss-Markov bias, the periodic
// resonator (stationary; exact double integrals of their autocorrelations
// over the two segments' windows) and the rate random walk (starting at 0 at
// the first sample: Cov = K^2 min(t, s)). Each equation |G^-1 (m - b)| = g
// sees the error along the segment's gravity; the bound is
// (J^T C^-1 J)^-1 with J the equations' Jacobian at the truth (central
// differences here) and C the equations' covariance.

// Integral over t in A, s in B of exp(lambda |t - s|), A = [a1, a2], B = [b1, b2], A before B or A = B.
std::complex<double> exp_double_integral(std::complex<double> lambda, double a1, double a2, double b1, double b2) {
  if (a1 == b1 && a2 == b2) {
    const double T = a2 - a1;
    return 2.0 * (-T / lambda + (std::exp(lambda * T) - 1.0) / (lambda * lambda));
  }
  return -(std::exp(lambda * (b2 - a2)) - std::exp(lambda * (b2 - a1)) - std::exp(lambda * (b1 - a2)) +
           std::exp(lambda * (b1 - a1))) /
         (lambda * lambda);
}

// Covariance of the means of one axis's error over windows A and B (times from the session's start).
double mean_covariance(const json& model, std::size_t axis, double dt, double a1, double a2, double b1, double b2) {
  const bool same = a1 == b1 && a2 == b2;
  const double TA = a2 - a1, TB = b2 - b1;
  double c = 0.0;
  const double N = model["white_noise_density"][axis];
  if (same) c += N * N / TA;
  const double gm = model["gm_sigma"][axis], tau = model["gm_tau_s"][axis];
  c += gm * gm * exp_double_integral(-1.0 / tau, a1, a2, b1, b2).real() / (TA * TB);
  // The resonator's autocorrelation: sigma^2 r^k (cos k theta + c sin k theta), r = exp(-alpha dt).
  const double sp = model["periodic_sigma"][axis], period = model["periodic_period_s"][axis];
  const double zeta = model["periodic_damping"][axis];
  const double wd = 2.0 * std::numbers::pi / period, w0 = wd / std::sqrt(1.0 - zeta * zeta), alpha = zeta * w0;
  const double r = std::exp(-alpha * dt), theta = wd * dt;
  const double cs = (1.0 - r * r) / (1.0 + r * r) / std::tan(theta);
  const std::complex<double> lambda(-alpha, wd), coef(1.0, -cs);
  c += sp * sp * (coef * exp_double_integral(lambda, a1, a2, b1, b2)).real() / (TA * TB);
  const double K = model["rate_random_walk"][axis];
  c += K * K * (same ? a1 + TA / 3.0 : 0.5 * (a1 + a2));
  return c;
}

struct Bound {
  Eigen::Vector3d scale_ppm;  // 1 sigma
  Eigen::Vector3d misalign_rad;  // xy, xz, yz
};

Bound cramer_rao(const Session& s, const Eigen::Matrix3d& G_true, const Eigen::Vector3d& b,
                 const Eigen::Vector3d& scale_ppm, const Eigen::Matrix3d& M_sym, double g) {
  const json& accel = s.sim.hidden["imu_error_model"]["accel"];
  const double t0 = s.sim.hidden["t0_s"].get<double>(), dt = 1.0 / s.sim.hidden["imu_rate_hz"].get<double>();
  const std::vector<StillSegment>& seg = s.cal.segments;
  const auto n = static_cast<Eigen::Index>(seg.size());
  // Parameters b, s, M_sym (xy, xz, yz); residual r_k(p) = |G(p)^-1 (m_k - b)| - g at noise-free means.
  Eigen::Matrix<double, 9, 1> p0;
  p0 << b, scale_ppm * 1e-6, M_sym(0, 1), M_sym(0, 2), M_sym(1, 2);
  auto gain = [](const Eigen::Matrix<double, 9, 1>& p) {
    Eigen::Matrix3d M;
    M << 0, p[6], p[7], p[6], 0, p[8], p[7], p[8], 0;
    Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
    S.diagonal() += p.segment<3>(3);
    return Eigen::Matrix3d(S * (Eigen::Matrix3d::Identity() + M));
  };
  std::vector<Eigen::Vector3d> m(static_cast<std::size_t>(n)), u(static_cast<std::size_t>(n));
  const json& pos = s.sim.hidden["positions"];
  EXPECT_EQ(pos.size(), seg.size()) << "one segment per position, in order";
  for (std::size_t k = 0; k < seg.size(); ++k) {
    u[k] = vec3(pos[k]["true_specific_force_b_m_s2"]).normalized();
    m[k] = G_true * (g * u[k]) + b;  // the noise-free mean
  }
  Eigen::MatrixXd J(n, 9);
  for (int j = 0; j < 9; ++j) {
    const double h = j < 3 ? 1e-6 : 1e-8;
    Eigen::Matrix<double, 9, 1> pp = p0, pm = p0;
    pp[j] += h;
    pm[j] -= h;
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const double rp = (gain(pp).inverse() * (m[kk] - pp.head<3>())).norm();
      const double rm = (gain(pm).inverse() * (m[kk] - pm.head<3>())).norm();
      J(k, j) = (rp - rm) / (2.0 * h);
    }
  }
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    for (Eigen::Index l = k; l < n; ++l) {
      const StillSegment &A = seg[static_cast<std::size_t>(k)], &B = seg[static_cast<std::size_t>(l)];
      double c = 0.0;
      for (std::size_t a = 0; a < 3; ++a) {
        const double ua = u[static_cast<std::size_t>(k)][static_cast<Eigen::Index>(a)];
        const double va = u[static_cast<std::size_t>(l)][static_cast<Eigen::Index>(a)];
        c += ua * va * mean_covariance(accel, a, dt, A.t_start_s - t0, A.t_end_s - t0, B.t_start_s - t0, B.t_end_s - t0);
      }
      C(k, l) = C(l, k) = c;
    }
  }
  const Eigen::MatrixXd F = J.transpose() * C.ldlt().solve(J);
  const Eigen::MatrixXd crb = F.inverse();
  Bound out;
  for (int i = 0; i < 3; ++i) {
    out.scale_ppm[i] = 1e6 * std::sqrt(crb(3 + i, 3 + i));
    out.misalign_rad[i] = std::sqrt(crb(6 + i, 6 + i));
  }
  return out;
}

// Ten units (seeds 101..110), each a 14-position session (the six faces and
// the eight corners) held 10 minutes per position: 2.4 h at 40 Hz, as a
// bench calibration with a cube jig would be done.
TEST(SixPositionFit, TenSimulatedUnitsRecoverTheirScaleAndMisalignment) {
  std::printf("seed | scale error [ppm] (CRB)                         | misalignment error [mrad] (CRB)\n");
  double worst_scale = 0.0, worst_mis = 0.0, worst_scale_ratio = 0.0, worst_mis_ratio = 0.0;
  for (std::uint64_t seed = 101; seed <= 110; ++seed) {
    Session s;
    simulate_and_fit(positions_options(seed, 14, 600.0), s);
    ASSERT_EQ(s.outcome, PositionsOutcome::Fitted) << s.why;
    ASSERT_TRUE(s.cal.fit.misalign_fitted);
    EXPECT_EQ(s.cal.fit.segments, 14u);
    const json& fx = s.sim.hidden["effects"];
    Eigen::Vector3d scale_true;
    Eigen::Matrix3d M_true;
    const Eigen::Matrix3d G_true = gain_of(vec3(fx["accel_scale"]), mat3(fx["accel_misalign"]));
    symmetric_form(G_true, scale_true, M_true);
    const Eigen::Vector3d b_true = vec3(s.sim.hidden["imu_error_model"]["accel"]["turn_on_bias"]);
    const Bound crb = cramer_rao(s, G_true, b_true, scale_true, M_true, s.cal.fit.gravity_m_s2);
    const Eigen::Vector3d se = s.cal.fit.accel_scale_ppm - scale_true;
    const Eigen::Matrix3d Me = s.cal.fit.accel_misalign_rad - M_true;
    const Eigen::Vector3d me(Me(0, 1), Me(0, 2), Me(1, 2));
    std::printf("%4llu | %6.0f %6.0f %6.0f (%3.0f %3.0f %3.0f) fit sigma %3.0f %3.0f %3.0f | %6.3f %6.3f %6.3f "
                "(%5.3f %5.3f %5.3f) fit sigma %5.3f\n",
                static_cast<unsigned long long>(seed), se[0], se[1], se[2], crb.scale_ppm[0], crb.scale_ppm[1],
                crb.scale_ppm[2], s.cal.fit.accel_scale_sigma_ppm[0], s.cal.fit.accel_scale_sigma_ppm[1],
                s.cal.fit.accel_scale_sigma_ppm[2], 1e3 * me[0], 1e3 * me[1], 1e3 * me[2],
                1e3 * crb.misalign_rad[0], 1e3 * crb.misalign_rad[1], 1e3 * crb.misalign_rad[2],
                1e3 * s.cal.fit.accel_misalign_sigma_rad(0, 1));
    for (int i = 0; i < 3; ++i) {
      // The targets, 200 ppm and 0.2 mrad, where the data can give
      // them; where they cannot (a 3-sigma bound above the target), 3 x the
      // Cramer-Rao bound: no unbiased fit of these segments does better than
      // the bound, and 3 sigma holds 99.7 % of a Gaussian error.
      EXPECT_LE(std::abs(se[i]), std::max(200.0, 3.0 * crb.scale_ppm[i])) << "seed " << seed << " axis " << i;
      EXPECT_LE(std::abs(me[i]), std::max(0.2e-3, 3.0 * crb.misalign_rad[i])) << "seed " << seed << " term " << i;
      worst_scale = std::max(worst_scale, std::abs(se[i]));
      worst_mis = std::max(worst_mis, std::abs(me[i]));
      worst_scale_ratio = std::max(worst_scale_ratio, std::abs(se[i]) / crb.scale_ppm[i]);
      worst_mis_ratio = std::max(worst_mis_ratio, std::abs(me[i]) / crb.misalign_rad[i]);
    }
  }
  std::printf("worst: scale %.0f ppm (%.2f x its CRB), misalignment %.3f mrad (%.2f x its CRB)\n", worst_scale,
              worst_scale_ratio, 1e3 * worst_mis, worst_mis_ratio);
}

}  // namespace
