// sinu calibrate --in STATIC_DATASET [--in ...] --out calib.json [--report DIR]
//                [--no-denoise] [--wavelet NAME --levels N] [--model METHOD:P] [--quiet]
//                [--latitude DEG] [--height M]
// The paper's Section 3 on static bench data: per axis mean (turn-on bias),
// denoise, GM1, AR(1..10) by Yule-Walker/Covariance/Burg, Allan deviation.
// A session held still in several attitudes (or several --in, one face
// each) is a multi-position calibration: the still segments are found, the
// noise models fitted on the longest, and the accelerometer's bias, scale and
// misalignment and the gyro bias fitted on all (calib.json "six_position").
#include <cstdio>
#include <string>
#include <vector>

#include "firmware/host/calibration/calib_json.hpp"
#include "firmware/host/calibration/calibration_run.hpp"
#include "firmware/host/calibration/progress_bar.hpp"
#include "firmware/host/calibration/report.hpp"
#include "firmware/host/calibration/six_position_run.hpp"
#include "firmware/cli/calibrate_command.hpp"
#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"

namespace sinu::cli {

namespace {

// Sessions longer than this get a progress bar (an 8 h session takes seconds).
constexpr double kLongSession_s = 600.0;
constexpr std::size_t kRowsPer8h = 1152000;  // 40 Hz; only for the reading bar's scale


bool parse_model(const std::string& text, calibration::ModelChoice& m) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) return false;
  const std::string method = text.substr(0, colon);
  int found = -1;
  for (std::size_t i = 0; i < calibration::kArMethods; ++i)
    if (method == calibration::kArMethodNames[i]) found = static_cast<int>(i);
  if (found < 0) return false;
  try {
    const int p = std::stoi(text.substr(colon + 1));
    if (p < 1 || p > static_cast<int>(calibration::kMaxArOrder)) return false;
    m.method = static_cast<calibration::ArMethod>(found);
    m.order = static_cast<std::size_t>(p);
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

}  // namespace

int run_calibrate(const CalibrateOptions& o) {
  calibration::ModelChoice model;
  if (!parse_model(o.model, model)) {
    std::fprintf(stderr, "sinu calibrate: --model '%s': expected METHOD:P with METHOD yule_walker|covariance|burg "
                         "and P in 1..10\n", o.model.c_str());
    return kExitUsage;
  }
  calibration::CalibrationRun run;
  if (o.no_denoise) {
    run.denoiser = calibration::no_denoiser();
  } else {
    std::string why;
    if (!calibration::make_wavelet_denoiser(o.wavelet, o.levels, run.denoiser, why)) {
      std::fprintf(stderr, "sinu calibrate: %s\n", why.c_str());
      return kExitUsage;
    }
  }
  std::vector<calibration::SessionStillParts> still;
  for (const std::string& in : o.inputs) {
    calibration::StaticSession session;
    dataset::Diagnostic err;
    calibration::ProgressBar reading("reading " + in, static_cast<double>(kRowsPer8h), !o.quiet);
    bool shown = false;
    const bool ok = calibration::load_static_session(in, session, err, [&](std::size_t rows) {
      shown = true;
      reading.update(static_cast<double>(rows));
    });
    if (shown) reading.finish();
    if (!ok) {
      std::fprintf(stderr, "sinu calibrate: %s\n", err.to_string().c_str());
      return kExitFailure;
    }
    if (session.rows_without_imu > 0 || session.gaps > 0) {
      std::fprintf(stderr, "sinu calibrate: %s: %zu rows without accelerometer/gyro values skipped, %zu gaps in time\n",
                   in.c_str(), session.rows_without_imu, session.gaps);
    }
    // More than 1 % (not the last row's): the accelerometer's noise is not its own at the shortest times.
    if ((session.accel_held + session.accel_interpolated) * 100 > session.imu[0].size()) {
      std::fprintf(stderr,
                   "sinu calibrate: %s: %zu samples without an accelerometer reading of their own (%zu "
                   "interpolated between rows, %zu held): its noise at the shortest averaging times reads low\n",
                   in.c_str(), session.accel_held + session.accel_interpolated, session.accel_interpolated,
                   session.accel_held);
    }
    // Held in one attitude: the whole session, as always; in several: the noise
    // models from its longest still segment (the multi-position fit below).
    still.push_back(calibration::find_still_parts(session, run.sessions.size()));
    const calibration::SessionStillParts& parts = still.back();
    if (const std::string moved = calibration::motion_in_session(session, parts.noise_begin, parts.noise_end);
        !moved.empty()) {
      std::fprintf(stderr, "sinu calibrate: %s: %s\n", in.c_str(), moved.c_str());
      return kExitFailure;
    }
    if (!parts.whole) session = calibration::slice_session(session, parts.noise_begin, parts.noise_end);
    calibration::ProgressBar fitting("fitting " + in, static_cast<double>(calibration::kImuAxes.size()),
                               !o.quiet && session.duration_s > kLongSession_s);
    double done = 0.0;
    run.sessions.push_back(calibration::calibrate_session(session, run.denoiser, model, [&] { fitting.update(++done); }));
    fitting.finish();
  }
  std::string why;
  calibration::GravityModel gravity;
  gravity.latitude_given = std::isfinite(o.latitude_deg);
  gravity.height_given = std::isfinite(o.height_m);
  if (gravity.latitude_given) gravity.latitude_deg = o.latitude_deg;
  if (gravity.height_given) gravity.height_m = o.height_m;
  calibration::SixPositionCalibration positions;
  switch (calibration::calibrate_positions(still, run.sessions, gravity, positions, why)) {
    case calibration::PositionsOutcome::SinglePosition: break;
    case calibration::PositionsOutcome::Failed:
      std::fprintf(stderr, "sinu calibrate: %s: %s\n", o.inputs.front().c_str(), why.c_str());
      return kExitFailure;
    case calibration::PositionsOutcome::Fitted: run.six_position = positions; break;
  }
  if (!calibration::write_calib_json(run, o.out, why)) {
    std::fprintf(stderr, "sinu calibrate: %s\n", why.c_str());
    return kExitFailure;
  }
  if (!o.report_dir.empty()) {
    if (!calibration::write_report(run, o.report_dir, why)) {
      std::fprintf(stderr, "sinu calibrate: %s\n", why.c_str());
      return kExitFailure;
    }
    std::printf("report: %s/report.md (plots: /usr/bin/python3 tools/plot_calibration.py %s)\n", o.report_dir.c_str(),
                o.report_dir.c_str());
  }
  std::printf("calibration: %s (%zu session%s, denoiser: %s, model: %s)\n", o.out.c_str(), run.sessions.size(),
              run.sessions.size() == 1 ? "" : "s", run.denoiser.name.c_str(), o.model.c_str());
  if (run.six_position) std::printf("%s", calibration::six_position_report(*run.six_position).c_str());
  return kExitOk;
}

void add_calibrate_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<CalibrateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "calibrate", "Fit GM, AR and Allan noise models to a static session (bench calibration)");
  cmd->add_option("--in", o->inputs, "Static dataset folder (imu.csv); repeat for the cross-dataset comparison")
      ->required();
  cmd->add_option("--out", o->out, "calib.json to write")->required();
  cmd->add_option("--report", o->report_dir, "Folder for report.md and the model-versus-data CSVs");
  cmd->add_flag("--no-denoise", o->no_denoise, "Fit the raw series (no wavelet denoising)");
  cmd->add_option("--wavelet", o->wavelet, "Wavelet of the denoiser")->capture_default_str();
  cmd->add_option("--levels", o->levels, "Decomposition levels of the denoiser")->capture_default_str()
      ->check(CLI::Range(1, 12));
  cmd->add_option("--model", o->model, "Model the EKF uses, METHOD:P")->capture_default_str();
  cmd->add_flag("--quiet", o->quiet, "No progress bar");
  cmd->add_option("--latitude", o->latitude_deg,
                  "Multi-position session: the bench's latitude [deg] for local gravity (default 45, and every scale "
                  "factor's sigma then holds |g|'s 0.15 % spread)")
      ->check(CLI::Range(-90.0, 90.0));
  cmd->add_option("--height", o->height_m, "Multi-position session: the bench's ellipsoidal height [m] (default 0, "
                                           "with a 300-m sigma)")
      ->check(CLI::Range(-500.0, 9000.0));
  cmd->callback([&action, o] { action = [o] { return run_calibrate(*o); }; });
}

}  // namespace sinu::cli
