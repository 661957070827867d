// Slow GNSS from power-on (the paper's Table 5 periods, 10-30 s between
// fixes, but from the first sample rather than after a converged start),
// INS/GPS only (`--no-mag`, the paper's filter): the unit levels at rest,
// takes off, and the first fix that shows it moving comes up to 30 s into
// the take-off run. Until then the take-off's steady acceleration looked to
// the levelling like a new rest 16 deg nose-up with 0.4 m/s^2 of bias along
// gravity, and the climb's vertical velocity was taken as zero with a
// 0.5 m/s sigma: at 10 s the solution fell 1.2 km (42 resets), at 30 s two
// resets. Now a fix that says "moving" undoes the rest windows since the last
// still fix, and a course alignment in motion leaves the vertical velocity
// a climb's sigma.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "host_tests/support/read_json.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

TEST(SlowGnssStart, InsGpsOnlyWithAFixEveryTenToThirtySecondsFromPowerOnStaysConverged) {
  TempDir dir;
  const std::string flight = dir.file("flight"), bench = dir.file("bench"), calib = dir.file("calib.json");
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", flight, "--seed", "13", "--duration", "900"}).exit_code, 0);
  ASSERT_EQ(run_sinu({"simulate", "static", "--out", bench, "--seed", "13", "--hours", "1"}).exit_code, 0);
  ASSERT_EQ(run_sinu({"calibrate", "--in", bench, "--out", calib, "--quiet"}).exit_code, 0);
  for (const char* period : {"10", "30"}) {
    const std::string out = dir.file(std::string("p") + period);
    const auto r = run_sinu({"replay", "--in", flight, "--truth", flight + "/truth.csv", "--calib", calib, "--no-mag",
                             "--gps-period", period, "--quiet", "--out", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto s = read_json(out + "/summary.json");
    EXPECT_EQ(s["health"]["status"], "ok") << period << " s: " << s["health"].dump();
    EXPECT_EQ(s["health"]["resets"]["position"].get<int>(), 0) << period << " s";
    // Dead reckoning between fixes 10 / 30 s apart on a consumer IMU: measured
    // 1.9 / 11.5 m horizontal, 2.2 / 14.6 m vertical, 0.7 / 0.9 deg (seeds 3,
    // 5, 21: 1.9-2.1 / 7.8-10.7 m, 2.3-2.9 / 13-14 m, up to 2.1 deg). Bounds
    // at about twice seed 13's; before the fix 78 / 12 m, 1244 / 44 m.
    const double limit_h = std::string(period) == "10" ? 4.0 : 25.0;
    const double limit_v = std::string(period) == "10" ? 5.0 : 30.0;
    EXPECT_LT(s["rmse"]["pos_h_m"].get<double>(), limit_h) << period << " s";
    EXPECT_LT(s["rmse"]["pos_v_m"].get<double>(), limit_v) << period << " s";
    EXPECT_LT(s["rmse"]["att_deg"].get<double>(), 3.0) << period << " s";
  }
}

}  // namespace
}  // namespace sinu::test
