// INS/GPS without a magnetometer (the paper's filter; a unit whose compass is
// off): on a long straight leg the heading is unobservable, and it was frozen
// in the updates, but the vertical gyro's error states were not. Learning
// from the weak horizontal accelerations, their estimate reached 0.3-0.4
// deg/s and turned the heading 55 deg in 150 s (seed 21, attitude RMSE 22
// deg; seed 5, 8 deg) with a sigma of 16 deg. Now they are frozen with it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "host_tests/support/nav_error.hpp"
#include "host_tests/support/read_json.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

TEST(HeadingWithoutMagnetometer, AStraightLegDoesNotTurnTheHeadingBeyondItsSigma) {
  for (const char* seed : {"21", "5"}) {
    TempDir dir;
    const std::string flight = dir.file("flight"), out = dir.file("out");
    // 600 s: take-off, turns to 330 s, then a 240-s straight leg at 30 m/s.
    ASSERT_EQ(run_sinu({"simulate", "flight", "--out", flight, "--seed", seed, "--duration", "600"}).exit_code, 0);
    const auto r = run_sinu({"replay", "--in", flight, "--no-mag", "--quiet", "--out", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto s = read_json(out + "/summary.json");
    EXPECT_EQ(s["health"]["status"], "ok") << seed;
    // Measured 3.7 / 3.0 deg (before: 22.0 / 8.0). What is left is the gyro
    // error the built-in model allows over the unobservable leg.
    EXPECT_LT(s["rmse"]["att_deg"].get<double>(), 6.0) << seed;
    // And the filter knows it: the last heading error within 3 of its sigmas
    // (measured 8 deg against a 38-deg sigma; before, 55 against 16).
    const ErrorSeries e = error_series(out + "/nav.csv", flight + "/truth.csv");
    ASSERT_FALSE(e.err_yaw_deg.empty());
    EXPECT_LT(std::abs(e.err_yaw_deg.back()), 3.0 * nav_value(out + "/nav.csv", "sigma_att_d_deg", NavRow::Last)) << seed;
  }
}

}  // namespace
}  // namespace sinu::test
