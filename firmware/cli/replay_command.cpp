// sinu replay --in DATASET|RAW [--truth truth.csv] [--calib calib.json]
//   --model gm|ar [--effects ...] [--gps-period S] [--outage START:DURATION,...] --out DIR
// Runs a dataset folder, or a raw HAL recording through the drivers, through
// the INS/EKF; writes nav.csv, innovations.csv and summary.json; prints the
// navigation summary.
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "firmware/cli/navigation_options.hpp"
#include "firmware/replay/replay_runner.hpp"

namespace sinu::app {

namespace {

struct ReplayCliOptions {
  NavigationCliOptions nav{"ar", ""};
  std::string outages;
};

std::string fmt_num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

void print_summary(const std::string& out_dir) {
  std::ifstream in(out_dir + "/summary.json");
  const nlohmann::json s = nlohmann::json::parse(in, nullptr, false);
  if (s.is_discarded()) return;
  auto num = [](const nlohmann::json& v) { return v.is_number() ? fmt_num(v.get<double>()) : std::string("n/a"); };
  const nlohmann::json& h = s["health"];
  const std::string status = h["status"].get<std::string>();
  std::printf("replay %s  model %s  states %d  aligned %s\n", s["dataset"].get<std::string>().c_str(),
              s["model"].get<std::string>().c_str(), s["states"].get<int>(), s["aligned"].get<bool>() ? "yes" : "NO");
  // A solution that was lost or reset says so before any figure.
  const auto resets = h["resets"]["position"].get<std::uint64_t>() + h["resets"]["velocity"].get<std::uint64_t>() +
                      h["resets"]["yaw"].get<std::uint64_t>();
  if (status == "lost") {
    std::printf("  SOLUTION LOST at the end of the data (lost %s s from t=%s): the figures below are not a navigation "
                "result\n", num(h["lost_s"]).c_str(), num(h["first_lost_t"]).c_str());
  } else if (status == "lost_and_recovered") {
    std::printf("  SOLUTION WAS LOST for %s s (from t=%s) and recovered by %llu reset(s)\n", num(h["lost_s"]).c_str(),
                num(h["first_lost_t"]).c_str(), static_cast<unsigned long long>(resets));
  } else if (status == "reset") {
    std::printf("  solution RESET to GNSS %llu time(s) (first at t=%s; position %s, velocity %s, yaw %s)\n",
                static_cast<unsigned long long>(resets), num(h["first_reset_t"]).c_str(),
                num(h["resets"]["position"]).c_str(), num(h["resets"]["velocity"]).c_str(),
                num(h["resets"]["yaw"]).c_str());
  } else if (status == "not_aligned") {
    std::printf("  NOT ALIGNED: no navigation solution (no rest period and no GNSS motion to align on)\n");
  }
  std::printf("  rmse: pos_h %s m  pos_v %s m  vel %s m/s  att %s deg  (%s truth points; GNSS alone: pos_h %s m  pos_v %s m)\n",
              num(s["rmse"]["pos_h_m"]).c_str(), num(s["rmse"]["pos_v_m"]).c_str(), num(s["rmse"]["vel_m_s"]).c_str(),
              num(s["rmse"]["att_deg"]).c_str(), num(s["rmse"]["truth_points"]).c_str(),
              num(s["gnss_only_rmse"]["pos_h_m"]).c_str(), num(s["gnss_only_rmse"]["pos_v_m"]).c_str());
  for (const auto& o : s["outages"]) {
    std::printf("  outage %.1f s +%.0f s: max horizontal drift %s m\n", o["start"].get<double>(), o["duration"].get<double>(),
                num(o["max_drift_h_m"]).c_str());
  }
  if (!s["outages"].empty()) std::printf("  outage drift RMS %s m\n", num(s["outage_max_drift_h_rms_m"]).c_str());
  std::printf("  NIS gnss_position mean %s (inside 95%%: %s), NEES mean %s (%d dof, inside 95%%: %s)\n",
              num(s["nis"]["gnss_position"]["mean"]).c_str(), num(s["nis"]["gnss_position"]["inside_95"]).c_str(),
              num(s["nees"]["mean"]).c_str(), s["nees"]["dof"].get<int>(), num(s["nees"]["inside_95"]).c_str());
  std::printf("  rejected: position %s velocity %s magnetometer %s; corrupt sentences %s\n",
              num(s["rejected"]["gnss_position"]).c_str(), num(s["rejected"]["gnss_velocity"]).c_str(),
              num(s["rejected"]["magnetometer"]).c_str(), num(s["corrupt_sentences"]).c_str());
  const nlohmann::json& imu = s["imu"];
  if (imu["clipped_samples"].get<double>() > 0 || imu["gaps"].get<double>() > 0 || imu["invalid"].get<double>() > 0 ||
      imu["non_increasing"].get<double>() > 0 || h["gnss_timeouts"].get<double>() > 0) {
    std::printf("  faults: IMU clipped %s samples, %s gaps (longest %s s), %s dropped (NaN %s, time %s); GNSS timeouts %s "
                "(%s s dead reckoning)\n",
                num(imu["clipped_samples"]).c_str(), num(imu["gaps"]).c_str(), num(imu["longest_gap_s"]).c_str(),
                fmt_num(imu["invalid"].get<double>() + imu["non_increasing"].get<double>()).c_str(),
                num(imu["invalid"]).c_str(), num(imu["non_increasing"]).c_str(), num(h["gnss_timeouts"]).c_str(),
                num(h["gnss_timeout_s"]).c_str());
  }
}

int run(ReplayCliOptions& c) {
  std::string error;
  replay::ReplayOptions& opt = c.nav.opt;
  if (!c.nav.resolve(error) || !replay::parse_outages(c.outages, opt.outages, error)) {
    std::fprintf(stderr, "sinu replay: %s\n", error.c_str());
    return kExitUsage;
  }
  replay::ReplayTotals totals;
  if (!replay::run_replay(opt, totals, error)) {
    std::fprintf(stderr, "sinu replay: %s\n", error.c_str());
    return kExitFailure;
  }
  if (!totals.note.empty()) std::fprintf(stderr, "sinu replay: note: %s\n", totals.note.c_str());
  if (!opt.quiet) print_summary(opt.out_dir);
  return kExitOk;
}

}  // namespace

void add_replay_command(CLI::App& app, Action& action) {
  auto c = std::make_shared<ReplayCliOptions>();
  replay::ReplayOptions& opt = c->nav.opt;
  CLI::App* sub = app.add_subcommand(
      "replay", "Replay a dataset or a raw recording through the INS/EKF and write the navigation solution");
  c->nav.add_to(*sub);
  sub->add_option("--gps-period", opt.gps_period_s, "Use one GPS epoch every S seconds (0: all)");
  sub->add_option("--outage", c->outages, "GPS outages START:DURATION[,...] in the dataset's t [s]");
  sub->add_option("--nav-rate", opt.nav_rate_hz, "nav.csv rows per second (0: every IMU sample)")->capture_default_str();
  sub->add_option("--out", opt.out_dir, "Output folder")->required();
  sub->add_flag("--quiet", opt.quiet, "Do not print the summary");
  sub->callback([&action, c] { action = [c] { return run(*c); }; });
}

}  // namespace sinu::app
