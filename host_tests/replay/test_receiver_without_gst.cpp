// A receiver that states no accuracy: GGA and RMC without GST (legal in the
// dataset contract, and what many receivers and simulators write). The fix
// sigma is then a guess, HDOP x UERE (2.5 m); the navigator learns a factor
// on it from the position innovations (estimator/nav/noise_adapter.hpp,
// learn_scale), and an RTK fix quality counts as a statement of its own
// (firmware/board/gnss_from_fix.cpp). Before, the guess was final: a receiver
// 2.4 times better than its HDOP said was fused 2.4 times too tightly (552
// position inflations, NEES inside its bounds 51 % of the time), the real
// quadcopter's u-blox (HDOP 1.6, 0.5-1 m) was trusted 4x too little, and the
// real drive's RTK fixes without GST had a 5-m sigma.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "host_tests/support/nmea_text.hpp"
#include "host_tests/support/read_json.hpp"
#include "host_tests/support/replay_helpers.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/shared_data.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

/// A copy of dataset `src` without GST sentences; with `hdop` non-empty, every
/// GGA's HDOP field is replaced by it (checksum recomputed).
std::string without_gst(const std::string& src, const std::string& dst, const std::string& hdop = "") {
  std::size_t dropped = 0, rewritten = 0;
  copy_dataset_editing_gps(src, dst, [&](std::string& line) {
    if (line.find("GST,") != std::string::npos) return (++dropped, false);
    const auto dollar = line.find('$'), star = line.rfind('*');
    if (hdop.empty() || line.find("GGA,") == std::string::npos || dollar == std::string::npos ||
        star == std::string::npos || star < dollar)
      return true;
    std::vector<std::string> f;
    std::istringstream fields(line.substr(dollar + 1, star - dollar - 1));
    for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
    if (f.size() > 8 && !f[8].empty()) {
      f[8] = hdop;
      std::string body = f[0];
      for (std::size_t i = 1; i < f.size(); ++i) body += "," + f[i];
      line = line.substr(0, dollar) + nmea_with_checksum(body);
      ++rewritten;
    }
    return true;
  });
  EXPECT_GT(dropped, 0u) << src << " had no GST to remove";
  if (!hdop.empty()) {
    EXPECT_GT(rewritten, 0u);
  }
  return dst;
}

// The simulator's receiver errs by 1.26 m per horizontal axis (GM 1.2 m over
// 120 s plus 0.4 m white; hidden.json) whatever its HDOP. Written as HDOP 0.3
// (a guess of 0.53 m, 2.4x too small) and HDOP 3.0 (5.3 m, 4.2x too large).
TEST(ReceiverWithoutGst, LearnsTheSigmaItsHdopGetsWrong) {
  TempDir dir;
  const std::string flight = dir.file("flight");
  ASSERT_EQ(run_sinu({"simulate", "flight", "--out", flight, "--seed", "5", "--duration", "900", "--hidden-out",
                      dir.file("hidden.json")})
                .exit_code,
            0);
  const auto hidden = read_json(dir.file("hidden.json"))["gps_error_model"];
  const double true_sigma_h = std::hypot(hidden["position_gm_sigma_ned_m"][0].get<double>(),
                                         hidden["position_white_sigma_ned_m"][0].get<double>());
  const auto stated = replay_summary({"replay", "--in", flight, "--quiet", "--out", dir.file("r_gst")});
  for (const std::string hdop : {"0.3", "3.0"}) {
    SCOPED_TRACE("HDOP " + hdop);
    const std::string in = without_gst(flight, dir.file("h" + hdop), hdop);
    const auto s = replay_summary({"replay", "--in", in, "--quiet", "--out", dir.file("r" + hdop)});
    EXPECT_EQ(s["health"]["status"], "ok") << s["health"].dump();
    const double guess = std::stod(hdop) * 2.5 / std::sqrt(2.0);
    // Learnt from 4500 fixes over a 60-s memory of GM-correlated errors:
    // measured 1.30 / 1.30 m against 1.26 (3 %); 15 % allows the GM's
    // 120-s correlation (a few independent samples per memory).
    EXPECT_NEAR(s["noise"]["gnss_position_scale_h"].get<double>() * guess, true_sigma_h, 0.15 * true_sigma_h);
    // Consistency: NEES inside its 95 % bounds 86 / 74 % of the time (the
    // receiver's GST: 86 %; the guess kept: 51 / 52 %). 0.65 sits between.
    EXPECT_GT(s["nees"]["inside_95"].get<double>(), 0.65);
    // Too tight a guess was widened by hand 552 times; learnt, once.
    EXPECT_LT(s["health"]["position_inflations"].get<int>(), 20);
    // Better than the fixes: 0.53 / 0.85 m against 1.41 (with GST 0.66 m;
    // the guess kept 1.30 / 0.65 m: a 4x too large sigma smooths this
    // simulator's GM error more, see docs/experiments.md).
    EXPECT_LT(s["rmse"]["pos_h_m"].get<double>(), 0.8 * s["gnss_only_rmse"]["pos_h_m"].get<double>());
    EXPECT_LT(s["rmse"]["pos_h_m"].get<double>(), 1.5 * stated["rmse"]["pos_h_m"].get<double>());
  }
}

TEST(ReceiverWithoutGst, TheRealQuadcopterBeatsItsFixesAgainstThePeer) {
  SINU_REQUIRE_SHARED(uav, "data/real/uav_log171");
  TempDir dir;
  const auto s = replay_summary({"replay", "--in", without_gst(uav, dir.file("nogst")), "--quiet", "--out", dir.file("r")});
  const auto stated = replay_summary({"replay", "--in", uav, "--quiet", "--out", dir.file("r_gst")});
  EXPECT_EQ(s["health"]["status"], "ok") << s["health"].dump();
  // HDOP 1.59 guesses 2.8 m; the learnt factor reaches its 0.2 floor (GST
  // said 0.5-1 m). Against the autopilot's EKF: measured 0.46 m against
  // 0.43 m with GST (the guess kept: 0.81 m). The fixes themselves: 0.52 m
  // taken as they come, 0.41 m each at the time of validity the filter
  // learnt (0.26 s before its arrival; the peer fuses them at its own delay).
  EXPECT_LT(s["rmse"]["pos_h_m"].get<double>(), 1.15 * stated["rmse"]["pos_h_m"].get<double>());
  EXPECT_LT(s["rmse"]["pos_h_m"].get<double>(), s["gnss_only_rmse"]["pos_h_m_at_configured_latency"].get<double>());
}

TEST(ReceiverWithoutGst, TheRealDriveTakesItsRtkQualityAsStated) {
  SINU_REQUIRE_SHARED(drive, "data/real/drive_0708");
  TempDir dir;
  const std::string outages = drive_0708_outages();
  const auto full = replay_summary({"replay", "--in", drive, "--outage", outages, "--quiet", "--out", dir.file("r_gst")});
  const auto s = replay_summary({"replay", "--in", without_gst(drive, dir.file("nogst")), "--outage", outages, "--quiet",
                         "--out", dir.file("r")});
  EXPECT_EQ(s["health"]["status"], "ok") << s["health"].dump();
  // GGA quality 4 (RTK fixed) and no HDOP: a 5-m sigma before (drift RMS
  // 3.96 m), now the RTK's floor of 0.2 m as with GST: 2.65 against 2.70 m.
  EXPECT_LT(s["outage_max_drift_h_rms_m"].get<double>(), 1.1 * full["outage_max_drift_h_rms_m"].get<double>());
}

}  // namespace
}  // namespace sinu::test
