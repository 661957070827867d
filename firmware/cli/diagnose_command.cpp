// sinu diagnose --in DATASET|RAW [--truth truth.csv] [--calib calib.json] [--model gm|ar] [--effects BASELINE]
//   [--candidates NAME,...] [--rounds N] --out DIR
// Compares the model with the measurements (innovations against the filter's
// own sigmas, per source and flight phase), tries each effect the EKF can
// estimate, names the one(s) missing and shows the error before and after.
#include <cstdio>
#include <string>

#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "firmware/diagnose/diagnose_runner.hpp"
#include "firmware/diagnose/diagnosis_report.hpp"

namespace sinu::app {

namespace {

// Nuisance states a navigation engineer always carries: the unit's turn-on
// biases and the receiver's slowly varying error.
constexpr const char* kDefaultBaseline = "accel_bias,gyro_bias,gps_position_bias";
// Everything else the EKF can estimate (the magnetometer's states come with it).
constexpr const char* kDefaultCandidates =
    "lever_arm,gps_latency,accel_scale,gyro_scale,accel_temp_bias,gyro_temp_bias,mag_soft_iron";

struct DiagnoseCliOptions {
  diag::DiagnoseOptions opt;
  std::string model = "gm";
  std::string effects = kDefaultBaseline;
  std::string candidates = kDefaultCandidates;
  std::vector<double> lever_arm;
};

int run(DiagnoseCliOptions& c) {
  std::string error;
  replay::ReplayOptions& r = c.opt.replay;
  if (c.model != "gm" && c.model != "ar") {
    std::fprintf(stderr, "sinu diagnose: --model must be gm or ar, not '%s'\n", c.model.c_str());
    return kExitUsage;
  }
  r.calib.kind = c.model == "gm" ? est::NoiseModelKind::GaussMarkov : est::NoiseModelKind::AutoRegressive;
  if (!replay::parse_effects(c.effects, r.effects, error) || !replay::parse_effects(c.candidates, c.opt.candidates, error)) {
    std::fprintf(stderr, "sinu diagnose: %s\n", error.c_str());
    return kExitUsage;
  }
  if (!c.lever_arm.empty()) {
    if (c.lever_arm.size() != 3) {
      std::fprintf(stderr, "sinu diagnose: --lever-arm needs three numbers x,y,z [m]\n");
      return kExitUsage;
    }
    r.lever_arm_b_m = {c.lever_arm[0], c.lever_arm[1], c.lever_arm[2]};
  }
  diag::Diagnosis d;
  if (!diag::run_diagnosis(c.opt, d, error)) {
    std::fprintf(stderr, "sinu diagnose: %s\n", error.c_str());
    return kExitFailure;
  }
  std::printf("%s  report: %s/report.md\n", diag::diagnosis_summary(c.opt, d).c_str(), r.out_dir.c_str());
  return kExitOk;
}

}  // namespace

void add_diagnose_command(CLI::App& app, Action& action) {
  auto c = std::make_shared<DiagnoseCliOptions>();
  replay::ReplayOptions& r = c->opt.replay;
  CLI::App* sub = app.add_subcommand("diagnose", "Compare the model with the measurements and name the missing effect");
  sub->add_option("--in", r.in_dir, "Dataset folder (imu.csv, gps.nmea, truth.csv optional) or raw recording")->required();
  sub->add_option("--truth", r.truth_path, "truth.csv to compare with (default: the dataset folder's, if any)");
  sub->add_option("--calib", r.calib_path, "calib.json from `sinu calibrate` (omitted: built-in defaults)");
  sub->add_option("--model", c->model, "Sensor-error model: gm or ar")->capture_default_str();
  sub->add_option("--effects", c->effects, "The model to start from (effect states)")->capture_default_str();
  sub->add_option("--candidates", c->candidates, "Effects to try, one at a time")->capture_default_str();
  sub->add_option("--rounds", c->opt.rounds, "How many effects to look for, one after the other")
      ->capture_default_str()
      ->check(CLI::Range(1, 5));
  sub->add_option("--gps-latency", r.gps_latency_s, "Known GPS latency [s]")->capture_default_str();
  sub->add_option("--lever-arm", c->lever_arm, "Known antenna minus IMU, body FRD [m], x,y,z")->delimiter(',');
  sub->add_option("--mag-declination", r.mag_declination_deg, "Site's declination [deg]: magnetometer heading at rest");
  sub->add_option("--mag-sigma", r.mag_sigma_uT, "Magnetometer noise, 1 sigma [uT]")->capture_default_str();
  sub->add_flag("--no-mag", [c](std::int64_t) { c->opt.replay.use_mag = false; }, "Do not fuse the magnetometer");
  sub->add_option("--out", r.out_dir, "Output folder: report.md, diagnosis.json, one replay folder per run")->required();
  sub->callback([&action, c] { action = [c] { return run(*c); }; });
}

}  // namespace sinu::app
