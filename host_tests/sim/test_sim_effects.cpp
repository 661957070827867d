// Each physical effect leaves its signature in the data. A flight with one
// effect is compared with the same seed without it (error-free sensors and
// GPS, so the difference is the effect alone, exact to the print precision).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>

#include "host_tests/sim/gps_log.hpp"
#include "host_tests/sim/sim_test_support.hpp"

using namespace sinu;
using namespace sinu::test;
namespace tc = dataset::truth_col;
namespace ic = dataset::imu_col;

namespace {

constexpr std::uint64_t kSeed = 21;
constexpr double kDuration_s = 900.0;  // long enough for turns between climb-out and descent

std::unique_ptr<SimRun> flight_with(const sim::Effects& fx) {
  auto r = std::make_unique<SimRun>();
  sim::SimOptions o = ideal_flight(kSeed, kDuration_s);
  o.effects = fx;
  run(*r, o);
  return r;
}

// imu.csv prints 9 significant digits: a value v is exact to 5e-9 |v|
// (relative), plus 1e-12 for values near zero.
double print_tol(double v) { return 1e-8 * std::abs(v) + 1e-12; }

class Effects : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    base_ = flight_with({}).release();
    base_imu_ = new std::vector<dataset::CsvRow>(base_->imu());
  }
  static void TearDownTestSuite() {
    delete base_imu_;
    delete base_;
  }

  // For every row: `check(base_row, effect_row)`; also the rows share t.
  static void compare_imu(const sim::Effects& fx,
                          const std::function<void(const dataset::CsvRow&, const dataset::CsvRow&)>& check) {
    const auto r = flight_with(fx);
    const auto rows = r->imu();
    ASSERT_EQ(rows.size(), base_imu_->size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
      ASSERT_EQ(rows[k].t(), (*base_imu_)[k].t());
      check((*base_imu_)[k], rows[k]);
      if (::testing::Test::HasFailure()) FAIL() << "row " << k;
    }
  }

  // got == A b + c, where b (the baseline row) and got are both printed:
  // b's rounding propagates through |A|.
  static void expect_map(const Eigen::Vector3d& got, const Eigen::Matrix3d& A, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c = Eigen::Vector3d::Zero(),
                         const Eigen::Vector3d& c_tol = Eigen::Vector3d::Zero()) {
    const Eigen::Vector3d want = A * b + c;
    const Eigen::Vector3d b_tol = b.unaryExpr([](double v) { return print_tol(v); });
    const Eigen::Vector3d tol = A.cwiseAbs() * b_tol;
    for (Eigen::Index i = 0; i < 3; ++i) ASSERT_NEAR(got[i], want[i], tol[i] + c_tol[i] + print_tol(got[i]));
  }
  static void expect_same(const Eigen::Vector3d& got, const Eigen::Vector3d& b) {
    for (Eigen::Index i = 0; i < 3; ++i) ASSERT_EQ(got[i], b[i]);
  }

  static SimRun* base_;
  static std::vector<dataset::CsvRow>* base_imu_;
};
SimRun* Effects::base_ = nullptr;
std::vector<dataset::CsvRow>* Effects::base_imu_ = nullptr;

}  // namespace

TEST_F(Effects, AccelScaleMultipliesEachAxis) {
  const Eigen::Vector3d ppm(8000, -5000, 3000);
  compare_imu({.accel_scale_ppm = ppm}, [&](const dataset::CsvRow& b, const dataset::CsvRow& e) {
    expect_map(triple(e, ic::ax), (Eigen::Vector3d::Ones() + 1e-6 * ppm).asDiagonal().toDenseMatrix(), triple(b, ic::ax));
    expect_same(triple(e, ic::gx), triple(b, ic::gx));  // gyro untouched
  });
}

TEST_F(Effects, GyroScaleMultipliesEachAxis) {
  const Eigen::Vector3d ppm(-20000, 15000, 10000);
  compare_imu({.gyro_scale_ppm = ppm}, [&](const dataset::CsvRow& b, const dataset::CsvRow& e) {
    expect_map(triple(e, ic::gx), (Eigen::Vector3d::Ones() + 1e-6 * ppm).asDiagonal().toDenseMatrix(), triple(b, ic::gx));
    expect_same(triple(e, ic::ax), triple(b, ic::ax));
  });
}

TEST_F(Effects, AccelMisalignmentMixesAxes) {
  Eigen::Matrix3d M;
  M << 0, 0.01, -0.008, 0.006, 0, 0.012, -0.01, 0.007, 0;
  compare_imu({.accel_misalign_rad = M}, [&](const dataset::CsvRow& b, const dataset::CsvRow& e) {
    // Level flight: ax and ay pick up ~1 % of the 9.8 m/s^2 on z.
    expect_map(triple(e, ic::ax), Eigen::Matrix3d::Identity() + M, triple(b, ic::ax));
  });
}

TEST_F(Effects, GyroMisalignmentMixesAxes) {
  Eigen::Matrix3d M;
  M << 0, -0.01, 0.009, 0.011, 0, -0.006, 0.008, 0.013, 0;
  compare_imu({.gyro_misalign_rad = M}, [&](const dataset::CsvRow& b, const dataset::CsvRow& e) {
    expect_map(triple(e, ic::gx), Eigen::Matrix3d::Identity() + M, triple(b, ic::gx));
  });
}

TEST_F(Effects, TemperatureBiasesFollowTheDieTemperature) {
  const Eigen::Vector3d ka(5e-3, -4e-3, 6e-3), kg(3e-4, -2e-4, 4e-4);
  double t_min = 1e9, t_max = -1e9;
  compare_imu({.accel_temp_bias_m_s2_per_degC = ka, .gyro_temp_bias_rad_s_per_degC = kg},
              [&](const dataset::CsvRow& b, const dataset::CsvRow& e) {
                const double dT = e.value[ic::temp] - sim::kTempBiasReference_degC;
                t_min = std::min(t_min, e.value[ic::temp]);
                t_max = std::max(t_max, e.value[ic::temp]);
                // The printed temperature's rounding propagates through k.
                const double t_tol = print_tol(e.value[ic::temp]);
                expect_map(triple(e, ic::ax), Eigen::Matrix3d::Identity(), triple(b, ic::ax), ka * dT,
                           ka.cwiseAbs() * t_tol);
                expect_map(triple(e, ic::gx), Eigen::Matrix3d::Identity(), triple(b, ic::gx), kg * dT,
                           kg.cwiseAbs() * t_tol);
              });
  EXPECT_GT(t_max - t_min, 3.0);  // the die warms up in flight, so the bias drifts
}

TEST_F(Effects, MagneticHardAndSoftIron) {
  const Eigen::Vector3d hard(12.0, -20.0, 8.0);
  Eigen::Matrix3d soft;
  soft << 1.08, 0.03, -0.02, 0.03, 0.93, 0.05, -0.02, 0.05, 1.11;
  compare_imu({.mag_hard_iron_uT = hard}, [&](const dataset::CsvRow& b, const dataset::CsvRow& e) {
    expect_map(triple(e, ic::mx), Eigen::Matrix3d::Identity(), triple(b, ic::mx), hard);
  });
  compare_imu({.mag_soft_iron = soft}, [&](const dataset::CsvRow& b, const dataset::CsvRow& e) {
    expect_map(triple(e, ic::mx), soft, triple(b, ic::mx));
  });
}

// A magnetometer turned by theta against the IMU reads the same field in
// axes turned by theta: the same strength, a direction |theta| away, and
// exp(-[theta x]) is the map (independent of the simulator's Eigen path:
// Rodrigues written out here).
TEST_F(Effects, MagneticMisalignmentTurnsTheField) {
  const Eigen::Vector3d theta(0.03, -0.02, 0.04);  // rad
  const double angle = theta.norm();
  const Eigen::Vector3d k = theta / angle;
  Eigen::Matrix3d K;
  K << 0.0, -k.z(), k.y(), k.z(), 0.0, -k.x(), -k.y(), k.x(), 0.0;
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() - std::sin(angle) * K + (1.0 - std::cos(angle)) * K * K;
  compare_imu({.mag_misalign_rad = theta}, [&](const dataset::CsvRow& b, const dataset::CsvRow& e) {
    expect_map(triple(e, ic::mx), R, triple(b, ic::mx));
  });
}

TEST_F(Effects, GyroGSensitivityAddsRatePerSpecificForce) {
  Eigen::Matrix3d G;
  G << 2e-4, 5e-5, -4e-5, -6e-5, 2.5e-4, 3e-5, 4e-5, -5e-5, -1.8e-4;
  compare_imu({.gyro_g_sensitivity_rad_s_per_m_s2 = G}, [&](const dataset::CsvRow& b, const dataset::CsvRow& e) {
    // The effect uses the true specific force; the baseline's printed one
    // differs by its rounding, which G (1e-4) scales far below the tolerance.
    expect_map(triple(e, ic::gx), Eigen::Matrix3d::Identity(), triple(b, ic::gx), G * triple(b, ic::ax));
  });
}

namespace {

// Error-free GGA positions of a flight by board time (fix epochs are IMU samples).
struct GgaPoint {
  double t, lat, lon, h;
};
std::vector<GgaPoint> gga_points(const SimRun& r) {
  std::vector<GgaPoint> out;
  const double utc_minus_board = r.result.hidden["utc"]["utc_minus_board_s"].get<double>();
  for (const GpsLine& g : read_gps_log(r.path("gps.nmea")))
    if (g.message)
      if (const auto* gga = std::get_if<drivers::GgaMessage>(&*g.message))
        out.push_back({board_time(*gga->utc_ms, utc_minus_board), *gga->lat_deg * kDeg, *gga->lon_deg * kDeg,
                       *gga->alt_msl_m + *gga->geoid_sep_m});
  return out;
}

// NED vector from truth row position to a geodetic point.
Eigen::Vector3d ned_from(const dataset::CsvRow& r, double lat, double lon, double h) {
  const double lat0 = r.value[tc::lat] * kDeg, h0 = r.value[tc::h];
  return {(lat - lat0) * (ref::r_meridian(lat0) + h0),
          std::remainder(lon - r.value[tc::lon] * kDeg, 2 * std::numbers::pi) * (ref::r_transverse(lat0) + h0) *
              std::cos(lat0),
          -(h - h0)};
}

std::size_t row_at(const std::vector<dataset::CsvRow>& truth, double t) {
  return static_cast<std::size_t>(std::llround((t - truth.front().t()) * 40.0));
}

}  // namespace

TEST_F(Effects, LeverArmPutsTheAntennaAtImuPlusCnbL) {
  const Eigen::Vector3d l(0.6, -0.2, -0.4);
  const auto r = flight_with({.lever_arm_b_m = l});
  const auto truth = r->truth();
  const auto fixes = gga_points(*r);
  ASSERT_GT(fixes.size(), 1900u);
  for (const GgaPoint& p : fixes) {
    const auto k = row_at(truth, p.t);
    ASSERT_LT(k, truth.size());
    // GGA prints 1e-6 arc-minutes (1.9 mm) and 1 mm of altitude: 5 mm bound.
    const Eigen::Vector3d d = ned_from(truth[k], p.lat, p.lon, p.h), want = ref::C_nb_of(truth[k]) * l;
    for (Eigen::Index i = 0; i < 3; ++i) ASSERT_NEAR(d[i], want[i], 5e-3) << "t " << p.t;
  }
}

TEST_F(Effects, LeverArmAddsRotationToTheAntennaVelocity) {
  // RMC speed of the antenna vs the IMU's: they differ by the horizontal part
  // of C_nb (omega x l) whenever the aircraft rotates (tenths of m/s here).
  const Eigen::Vector3d l(0.0, 1.0, -0.5);  // on the right wing: turns change its speed
  const auto with = read_gps_log(flight_with({.lever_arm_b_m = l})->path("gps.nmea"));
  const auto base = read_gps_log(base_->path("gps.nmea"));
  ASSERT_EQ(with.size(), base.size());
  double max_diff = 0.0;
  for (std::size_t i = 0; i < with.size(); ++i)
    if (with[i].message && std::holds_alternative<drivers::RmcMessage>(*with[i].message))
      max_diff = std::max(max_diff, std::abs(*std::get<drivers::RmcMessage>(*with[i].message).speed_m_s -
                                             *std::get<drivers::RmcMessage>(*base[i].message).speed_m_s));
  // Yaw rate in a 35 deg turn at 40 m/s is 0.17 rad/s: 1 m of lever gives 0.17 m/s.
  EXPECT_GT(max_diff, 0.05);
  EXPECT_LT(max_diff, 1.0);
}

TEST_F(Effects, GpsLatencyMakesEachFixOlderThanItsStamp) {
  const double L = 0.15;
  const auto r = flight_with({.gps_latency_s = L});
  const auto truth = r->truth();
  double max_lag_m = 0.0;
  for (const GgaPoint& p : gga_points(*r)) {
    const double ts = p.t - L;
    if (ts < truth.front().t()) continue;
    const auto k = static_cast<std::size_t>(std::floor((ts - truth.front().t()) * 40.0));
    ASSERT_LT(k + 1, truth.size());
    // Truth linearly interpolated at t - L: interpolation error a dt^2 / 8 <
    // 7 m/s^2 * 0.025^2 / 8 = 0.6 mm, plus 5 mm of print rounding.
    const double w = (ts - truth[k].t()) / (truth[k + 1].t() - truth[k].t());
    const Eigen::Vector3d a = ned_from(truth[k], p.lat, p.lon, p.h), b = ned_from(truth[k + 1], p.lat, p.lon, p.h);
    const Eigen::Vector3d at_sample = (1.0 - w) * a + w * b;
    for (Eigen::Index i = 0; i < 3; ++i) ASSERT_NEAR(at_sample[i], 0.0, 6e-3) << "t " << p.t;
    // ... and it is metres away from where the IMU is at the stamp (v L).
    max_lag_m = std::max(max_lag_m, ned_from(truth[row_at(truth, p.t)], p.lat, p.lon, p.h).norm());
  }
  EXPECT_GT(max_lag_m, 0.15 * 30.0);
  // The arrival time does not reveal it: still stamp + 45 ms for GGA
  // (arrival printed to 1 us).
  const double utc_minus_board = r->result.hidden["utc"]["utc_minus_board_s"].get<double>();
  for (const GpsLine& g : read_gps_log(r->path("gps.nmea"))) {
    const auto* gga = g.message ? std::get_if<drivers::GgaMessage>(&*g.message) : nullptr;
    if (gga) {
      EXPECT_NEAR(g.arrival_s - board_time(*gga->utc_ms, utc_minus_board), 0.045, 2e-6);
    }
  }
}

TEST_F(Effects, EffectsLeaveTrajectoryAndNoiseUnchanged) {
  sim::Effects all;
  sim::Rng rng(3, sim::RngStream::Effects);
  all = sim::draw_random_effects(11, rng);
  ASSERT_EQ(all.count(), 11u);
  const auto r = flight_with(all);
  const auto truth = r->truth(), base_truth = base_->truth();
  ASSERT_EQ(truth.size(), base_truth.size());
  for (std::size_t k = 0; k < truth.size(); ++k)
    for (std::size_t c = 0; c < tc::count; ++c) ASSERT_EQ(truth[k].value[c], base_truth[k].value[c]);
}
