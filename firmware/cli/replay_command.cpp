// sinu replay --in DATASET|RAW [--truth truth.csv] [--calib calib.json]
//   --model gm|ar [--effects ...] [--gps-period S] [--outage START:DURATION,...] --out DIR
// Runs a dataset folder, or a raw HAL recording through the drivers, through
// the INS/EKF; writes nav.csv, innovations.csv and summary.json; prints the
// navigation summary.
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "firmware/cli/board_options.hpp"
#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "firmware/replay/replay_runner.hpp"

namespace sinu::app {

namespace {

struct ReplayCliOptions {
  replay::ReplayOptions opt;
  std::string model = "ar";
  std::string effects, outages;
  std::vector<double> lever_arm;
  ImuOptions imu;  // for a raw recording: the driver settings it was recorded with
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
  std::printf("replay %s  model %s  states %d  aligned %s\n", s["dataset"].get<std::string>().c_str(),
              s["model"].get<std::string>().c_str(), s["states"].get<int>(), s["aligned"].get<bool>() ? "yes" : "NO");
  std::printf("  rmse: pos_h %s m  pos_v %s m  vel %s m/s  att %s deg  (%s truth points)\n",
              num(s["rmse"]["pos_h_m"]).c_str(), num(s["rmse"]["pos_v_m"]).c_str(), num(s["rmse"]["vel_m_s"]).c_str(),
              num(s["rmse"]["att_deg"]).c_str(), num(s["rmse"]["truth_points"]).c_str());
  for (const auto& o : s["outages"]) {
    std::printf("  outage %.1f s +%.0f s: max horizontal drift %s m\n", o["start"].get<double>(), o["duration"].get<double>(),
                num(o["max_drift_h_m"]).c_str());
  }
  if (!s["outages"].empty()) std::printf("  outage drift RMS %s m\n", num(s["outage_max_drift_h_rms_m"]).c_str());
  std::printf("  NIS gnss_position mean %s (inside 95%%: %s), NEES mean %s (%d dof, inside 95%%: %s)\n",
              num(s["nis"]["gnss_position"]["mean"]).c_str(), num(s["nis"]["gnss_position"]["inside_95"]).c_str(),
              num(s["nees"]["mean"]).c_str(), s["nees"]["dof"].get<int>(), num(s["nees"]["inside_95"]).c_str());
  std::printf("  rejected: position %s velocity %s; corrupt sentences %s\n", num(s["rejected"]["gnss_position"]).c_str(),
              num(s["rejected"]["gnss_velocity"]).c_str(), num(s["corrupt_sentences"]).c_str());
}

int run(ReplayCliOptions& c) {
  std::string error;
  if (c.model == "gm") {
    c.opt.calib.kind = est::NoiseModelKind::GaussMarkov;
  } else if (c.model == "ar") {
    c.opt.calib.kind = est::NoiseModelKind::AutoRegressive;
  } else {
    std::fprintf(stderr, "sinu replay: --model must be gm or ar, not '%s'\n", c.model.c_str());
    return kExitUsage;
  }
  if (!replay::parse_effects(c.effects, c.opt.effects, error) || !replay::parse_outages(c.outages, c.opt.outages, error)) {
    std::fprintf(stderr, "sinu replay: %s\n", error.c_str());
    return kExitUsage;
  }
  if (!c.lever_arm.empty()) {
    if (c.lever_arm.size() != 3) {
      std::fprintf(stderr, "sinu replay: --lever-arm needs three numbers x,y,z [m]\n");
      return kExitUsage;
    }
    c.opt.lever_arm_b_m = {c.lever_arm[0], c.lever_arm[1], c.lever_arm[2]};
  }
  if (!c.imu.to_config(c.opt.imu, error)) {
    std::fprintf(stderr, "sinu replay: %s\n", error.c_str());
    return kExitUsage;
  }
  replay::ReplayTotals totals;
  if (!replay::run_replay(c.opt, totals, error)) {
    std::fprintf(stderr, "sinu replay: %s\n", error.c_str());
    return kExitFailure;
  }
  if (!totals.note.empty()) std::fprintf(stderr, "sinu replay: note: %s\n", totals.note.c_str());
  if (!c.opt.quiet) print_summary(c.opt.out_dir);
  return kExitOk;
}

}  // namespace

void add_replay_command(CLI::App& app, Action& action) {
  auto c = std::make_shared<ReplayCliOptions>();
  CLI::App* sub = app.add_subcommand(
      "replay", "Replay a dataset or a raw recording through the INS/EKF and write the navigation solution");
  sub->add_option("--in", c->opt.in_dir,
                  "Dataset folder (imu.csv, gps.nmea, truth.csv), or a raw recording (sinu record, sinu convert) "
                  "replayed through the HAL and drivers")
      ->required();
  sub->add_option("--truth", c->opt.truth_path, "truth.csv to compare with (default: the dataset folder's, if any)");
  sub->add_option("--calib", c->opt.calib_path,
                  "calib.json from `sinu calibrate`; omitted: built-in defaults (README, 'sinu replay')");
  sub->add_option("--model", c->model, "Sensor-error model: gm (GM1, 15 states) or ar (AR(p), 9+6p states)")
      ->capture_default_str();
  sub->add_option("--ar-method", c->opt.calib.ar_method, "AR estimator in calib.json: burg, yule_walker, covariance")
      ->capture_default_str();
  sub->add_option("--ar-order", c->opt.calib.ar_order, "AR order p (1..4)")->capture_default_str();
  sub->add_option("--effects", c->effects,
                  "Extra states: accel_scale,gyro_scale,lever_arm,gps_latency,accel_temp_bias,gyro_temp_bias");
  sub->add_option("--gps-period", c->opt.gps_period_s, "Use one GPS epoch every S seconds (0: all)");
  sub->add_option("--outage", c->outages, "GPS outages START:DURATION[,...] in the dataset's t [s]");
  sub->add_option("--gps-latency", c->opt.gps_latency_s, "GPS latency: fix valid at arrival minus this [s]")
      ->capture_default_str();
  sub->add_option("--lever-arm", c->lever_arm, "Antenna minus IMU in body FRD [m], x,y,z")->delimiter(',');
  sub->add_option("--nav-rate", c->opt.nav_rate_hz, "nav.csv rows per second (0: every IMU sample)")->capture_default_str();
  sub->add_option("--denoise", c->opt.denoise,
                  "Wavelet denoiser in front of the INS: auto (calib.json's), none, or WAVELET:LEVELS (db4:3)")
      ->capture_default_str();
  sub->add_option("--gate", c->opt.gate_sigma, "Innovation gate [sigma]")->capture_default_str();
  sub->add_option("--out", c->opt.out_dir, "Output folder")->required();
  sub->add_option("--gps-vel-sigma", c->opt.sigma.velocity_sigma_m_s,
                  "GNSS velocity noise per axis, 1 sigma [m/s] (NMEA carries none)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub->add_option("--mag-sigma", c->opt.mag_sigma_uT, "Magnetometer noise per axis, 1 sigma [uT]")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub->add_option("--mag-declination", c->opt.mag_declination_deg,
                  "Site's magnetic declination [deg, east +]: align heading with the magnetometer at rest "
                  "(default: from the GNSS course once moving)");
  sub->add_flag("--no-mag", [c](std::int64_t) { c->opt.use_mag = false; },
                "Do not fuse the magnetometer even when imu.csv has one");
  sub->add_flag("--quiet", c->opt.quiet, "Do not print the summary");
  c->imu.add_to(*sub);
  sub->callback([&action, c] { action = [c] { return run(*c); }; });
}

}  // namespace sinu::app
