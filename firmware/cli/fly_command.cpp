// sinu fly [--config /etc/sinu/sinu.toml] [options that override it]
//   [--emulate DATASET [--speed X] [--fault KIND:START:DURATION,...]]
// The navigation unit on the companion computer: probe the sensors,
// configure the receiver, align (in motion too), navigate on every
// data-ready edge, send the solution to the outputs the configuration turns
// on; a health line a second on stderr. With --emulate the same loop runs on
// the host against a dataset (host/emulate): hardware in the loop.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>

#include "firmware/board/config/fly_setup.hpp"
#include "firmware/board/fly_loop.hpp"
#include "firmware/board/output_devices.hpp"
#include "firmware/cli/board_options.hpp"
#include "firmware/cli/board_session.hpp"
#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "firmware/cli/stop_signal.hpp"

namespace sinu::cli {

namespace {

struct FlyOptions {
  BoardOptions board;
  std::string config;
  double duration_s = 0.0;
  bool stats = false;
  double health_period_s = 1.0;
  double log_rate_hz = 10.0;
  std::string record;
  EmulateRequest emulate;
};

void print_end(const board::FlyLoop& loop, const board::OutputDevices& outputs, bool stats) {
  const auto& imu = loop.board().imu().counters();
  const auto& b = loop.board().counters();
  const est::NavCounters& n = loop.unit().navigator().counters();
  const est::SensorScaleVerdict& units = loop.unit().navigator().scale_verdict();
  char refused[96] = "";
  if (units.accel_refused) {
    std::snprintf(refused, sizeof refused,
                  "NOT ALIGNED: the accelerometer reads %.3gx gravity and the turns (its scale?)",
                  units.specific_force_over_gravity);
  } else if (units.gyro_refused) {
    std::snprintf(refused, sizeof refused, "NOT ALIGNED: the gyro scatters %.3g rad/s at rest (its scale?)",
                  units.gyro_std_at_rest_rad_s);
  }
  std::fprintf(stderr,
               "sinu fly: end: %llu IMU samples (%llu polled, %llu I2C errors, %llu re-inits; %llu data-ready "
               "timeouts); GPS %llu sentences corrupt, %llu garbage bytes; %llu solutions, %s\n",
               static_cast<unsigned long long>(imu.samples), static_cast<unsigned long long>(imu.polled),
               static_cast<unsigned long long>(imu.i2c_errors), static_cast<unsigned long long>(imu.reinits),
               static_cast<unsigned long long>(b.edge_timeouts),
               static_cast<unsigned long long>(loop.board().gps_counters().sentences.corrupt()),
               static_cast<unsigned long long>(loop.board().gps_counters().framing.noise_bytes),
               static_cast<unsigned long long>(loop.solutions()),
               units.accel_refused || units.gyro_refused ? refused
               : !loop.unit().navigator().aligned() ? "NOT ALIGNED"
               : n.lost_total_s > 0.0            ? "solution was LOST at times"
               : n.resets() > 0                  ? "solution reset to GNSS at times"
                                                 : "solution ok");
  if (const est::AlignmentResult& a = loop.unit().navigator().alignment_result(); std::isfinite(a.course_turn_rad))
    std::fprintf(stderr, "sinu fly: heading turned %.1f deg from the GNSS course at t=%.1f s (%s)\n",
                 a.course_turn_rad * 180.0 / std::numbers::pi, a.course_turn_t_s, est::kCourseTurnedCause);
  if (!loop.unit().state_note().empty())  // the state file: used, not (why), not written
    std::fprintf(stderr, "sinu fly: %s\n", loop.unit().state_note().c_str());
  std::fprintf(stderr, "sinu fly: outputs: %s\n", outputs.summary().c_str());
  if (stats) {
    const board::LoopStats& s = loop.stats();
    std::printf("loop time per sample (data-ready edge to outputs written): median %.1f us, worst %.1f us, %llu samples\n",
                static_cast<double>(s.median_ns()) * 1e-3, static_cast<double>(s.worst_ns()) * 1e-3,
                static_cast<unsigned long long>(s.count()));
  }
}

int run_fly(const FlyOptions& o) {
  std::string error;
  board::FlyConfig cfg;
  drivers::Icm20948Config imu;
  board::NavUnitConfig unit;
  if (!o.board.load(o.config, cfg, error) || !board::imu_config(cfg.imu, imu, error) ||
      !board::nav_unit_config(cfg, unit, error)) {
    std::fprintf(stderr, "sinu fly: %s\n", error.c_str());
    return kExitUsage;
  }
  std::error_code ec;
  if (!unit.calib_path.empty() && !std::filesystem::exists(unit.calib_path, ec)) {
    std::fprintf(stderr, "sinu fly: no calibration at %s: the built-in sensor model (run `sinu bench` on the board)\n",
                 unit.calib_path.c_str());
    unit.calib_path.clear();
  }
  if (!o.record.empty()) {
    cfg.recording.enabled = true;
    cfg.recording.path = o.record;
  }
  const std::string record = cfg.recording.enabled ? cfg.recording.path : "";
  board::OutputDevices outputs;
  if (!outputs.open(cfg.outputs, error)) {
    std::fprintf(stderr, "sinu fly: %s\n", error.c_str());
    return kExitFailure;
  }
  board::FlyOutputs fly_outputs = outputs.outputs();
  fly_outputs.log_period_s = o.log_rate_hz > 0.0 ? 1.0 / o.log_rate_hz : 0.0;
  BoardSession session;
  bool usage = false;
  if (!session.open(cfg, imu, record, o.emulate, error, usage)) {
    std::fprintf(stderr, "sinu fly: %s\n", error.c_str());
    return usage ? kExitUsage : kExitFailure;
  }
  board::FlyLoopConfig loop_cfg;
  loop_cfg.health_period_s = o.health_period_s;
  loop_cfg.edge_wall_ns = session.edge_wall_ns();
  loop_cfg.recording = session.writer();
  auto loop = std::make_unique<board::FlyLoop>(session.devices(), imu, fly_outputs, session.wall_clock(), loop_cfg);
  if (!loop->init(unit, error)) {
    std::fprintf(stderr, "sinu fly: %s\n", error.c_str());
    return kExitFailure;
  }
  install_stop_signals();
  loop->run(&stop_requested(), static_cast<hal::TimeNs>(o.duration_s * 1e9));
  int rc = kExitOk;
  if (!loop->close_log(error)) {
    std::fprintf(stderr, "sinu fly: %s\n", error.c_str());
    rc = kExitFailure;
  }
  if (loop_cfg.recording && !loop_cfg.recording->close()) {
    std::fprintf(stderr, "sinu fly: %s\n", loop_cfg.recording->error().c_str());
    rc = kExitFailure;
  }
  if (!session.error().empty()) {
    std::fprintf(stderr, "sinu fly: %s\n", session.error().c_str());
    rc = kExitFailure;
  }
  print_end(*loop, outputs, o.stats);
  return rc;
}

}  // namespace

void add_fly_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<FlyOptions>();
  CLI::App* cmd = app.add_subcommand("fly", "Run the navigation unit on the companion computer");
  cmd->add_option("--config", o->config,
                  "sinu.toml (default: /etc/sinu/sinu.toml if it exists); the options below override it");
  o->board.add_devices(*cmd);
  o->board.add_imu(*cmd);
  using board::FlyConfig;
  o->board.add(*cmd, "--calib", [](FlyConfig& c) -> auto& { return c.navigation.calibration; },
               "calib.json from sinu bench / sinu calibrate (navigation.calibration)");
  o->board.add(*cmd, "--model-file", [](FlyConfig& c) -> auto& { return c.navigation.model_file; },
               "Effects known from earlier flights, from sinu diagnose --apply (navigation.model_file)");
  o->board.add(*cmd, "--state-file", [](FlyConfig& c) -> auto& { return c.navigation.state_file; },
               "The unit's learnt state, saved every 5 s; a restart within 10 min starts from it "
               "(navigation.state_file; \"\": none)");
  o->board.add(*cmd, "--model", [](FlyConfig& c) -> auto& { return c.navigation.model; }, "Sensor-error model: gm or ar")
      ->check(CLI::IsMember({"gm", "ar"}));
  o->board.add(*cmd, "--vehicle", [](FlyConfig& c) -> auto& { return c.navigation.vehicle; }, "air or ground")
      ->check(CLI::IsMember({"air", "ground"}));
  o->board.add(*cmd, "--log", [](FlyConfig& c) -> auto& { return c.outputs.log.path; },
               "Navigation log (nav.csv columns) (outputs.log.path)");
  cmd->add_option("--record", o->record, "Also record the raw HAL traffic to this file (recording.path)");
  cmd->add_option("--duration", o->duration_s, "Stop after this many seconds of board time (0: until stopped)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--log-rate", o->log_rate_hz, "Navigation log rows per second (0: every solution)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--stats", o->stats, "At the end, the loop's time per sample: median and worst case");
  cmd->add_option("--health-period", o->health_period_s, "Seconds between health lines (0: none)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--emulate", o->emulate.dataset,
                  "Rehearsal (on the host, or on the board to time its CPU): the sensors played by this dataset (ICM-20948 emulator, fake data-ready line, GPS "
                  "bytes through a pty)");
  cmd->add_option("--speed", o->emulate.speed, "With --emulate: times real time (1: real time, 0: as fast as possible)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--fault", o->emulate.faults,
                  "With --emulate: faults KIND:START:DURATION[,...] in the dataset's t [s]; KIND i2c-stop, "
                  "gps-garbage, drdy-lost");
  cmd->callback([&action, o] { action = [o] { return run_fly(*o); }; });
}

}  // namespace sinu::cli
