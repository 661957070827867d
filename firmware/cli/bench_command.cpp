// sinu bench [--config sinu.toml] --hours H --out DIR
// Bench calibration on the board: records a static session through the
// drivers (DIR/session: imu.csv, gps.nmea) with a progress bar and ETA,
// warns at once and marks the data (DIR/bench.json) if the board moves or
// the temperature steps, then runs `sinu calibrate` on it (DIR/calib.json,
// DIR/report/) and puts calib.json where the configuration says `sinu fly`
// reads it (navigation.calibration).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "firmware/board/config/fly_setup.hpp"
#include "firmware/cli/board_options.hpp"
#include "firmware/cli/board_session.hpp"
#include "firmware/cli/calibrate_command.hpp"
#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "firmware/cli/stop_signal.hpp"
#include "firmware/host/calibration/bench_monitor.hpp"
#include "firmware/host/calibration/progress_bar.hpp"
#include "firmware/host/convert/dataset_sink.hpp"

namespace sinu::cli {

namespace {

struct BenchOptions {
  BoardOptions board;
  std::string config, out;
  double hours = 8.0;
  bool quiet = false;
  EmulateRequest emulate;
};

/// Writes the session, watches it, shows the progress.
class BenchSink final : public board::BoardSink {
 public:
  BenchSink(convert::DatasetSink& session, calibration::ProgressBar& bar, double duration_s, bool quiet)
      : session_(session), bar_(bar), duration_s_(duration_s), quiet_(quiet) {}
  void on_imu(const drivers::ImuSample& s) override {
    session_.on_imu(s);
    const double t = hal::ns_to_s(s.t_ns);
    if (!started_) t0_ = t, started_ = true;
    if (monitor_.add(t, s.specific_force_b_m_s2, s.angular_rate_b_rad_s, s.temp_degC)) warn();
    bar_.update(std::min(duration_s_, t - t0_));
  }
  void on_sentence(hal::TimeNs t, std::string_view sentence) override { session_.on_sentence(t, sentence); }
  void on_fix(const drivers::GpsFix& f) override { session_.on_fix(f); }
  const calibration::BenchMonitor& monitor() const { return monitor_; }
  double t0() const { return t0_; }

 private:
  void warn() {
    const calibration::BenchMark& m = monitor_.marks().back();
    if (quiet_) return;
    std::fprintf(stderr, "\nsinu bench: WARNING at %.0f s: %s (%.2f %s): the session is marked there (bench.json); "
                 "the noise models assume a still board at one temperature\n",
                 m.start_s - t0_, m.event == calibration::BenchEvent::Moved ? "the board moved" : "the temperature stepped",
                 m.size, m.event == calibration::BenchEvent::Moved ? "deg or deg/s" : "degC");
  }
  convert::DatasetSink& session_;
  calibration::ProgressBar& bar_;
  calibration::BenchMonitor monitor_;
  double duration_s_;
  bool quiet_;
  bool started_ = false;
  double t0_ = 0.0;
};

bool write_marks(const std::string& path, const BenchSink& sink, double duration_s, std::uint64_t samples) {
  nlohmann::json marks = nlohmann::json::array();
  for (const calibration::BenchMark& m : sink.monitor().marks()) {
    marks.push_back({{"event", calibration::bench_event_name(m.event)}, {"start_t", m.start_s}, {"end_t", m.end_s},
                     {"size", m.size}});
  }
  std::ofstream out(path);
  out << nlohmann::json{{"duration_s", duration_s}, {"imu_samples", samples}, {"still", marks.empty()}, {"marks", marks}}
             .dump(2)
      << "\n";
  return static_cast<bool>(out);
}

int run_bench(const BenchOptions& o) {
  std::string error;
  board::FlyConfig cfg;
  drivers::Icm20948Config imu;
  if (!o.board.load(o.config, cfg, error) || !board::imu_config(cfg.imu, imu, error)) {
    std::fprintf(stderr, "sinu bench: %s\n", error.c_str());
    return kExitUsage;
  }
  namespace fs = std::filesystem;
  const fs::path out(o.out), session_dir = out / "session";
  std::error_code ec;
  fs::create_directories(out, ec);
  BoardSession board_session;
  bool usage = false;
  if (!board_session.open(cfg, imu, "", o.emulate, error, usage)) {
    std::fprintf(stderr, "sinu bench: %s\n", error.c_str());
    return usage ? kExitUsage : kExitFailure;
  }
  convert::DatasetSink session;
  if (!session.open(session_dir.string())) {
    std::fprintf(stderr, "sinu bench: %s\n", session.error().c_str());
    return kExitFailure;
  }
  const double duration_s = o.hours * 3600.0;
  calibration::ProgressBar bar("bench " + session_dir.string(), duration_s, !o.quiet);
  BenchSink sink(session, bar, duration_s, o.quiet);
  install_stop_signals();
  board::BoardLoop loop(board_session.devices(), imu);
  loop.run(sink, &stop_requested(), static_cast<hal::TimeNs>(duration_s * 1e9) + 1'000'000'000);  // + the driver's start
  bar.finish();
  if (!session.close()) {
    std::fprintf(stderr, "sinu bench: %s\n", session.error().c_str());
    return kExitFailure;
  }
  if (!board_session.error().empty()) {
    std::fprintf(stderr, "sinu bench: %s\n", board_session.error().c_str());
    return kExitFailure;
  }
  const auto& c = loop.imu().counters();
  const std::string marks_path = (out / "bench.json").string();
  if (!write_marks(marks_path, sink, session.rows() ? duration_s : 0.0, c.samples)) {
    std::fprintf(stderr, "sinu bench: %s: write failed\n", marks_path.c_str());
    return kExitFailure;
  }
  std::fprintf(stderr, "sinu bench: %llu samples (%llu I2C errors) in %s; %zu mark(s) in %s\n",
               static_cast<unsigned long long>(c.samples), static_cast<unsigned long long>(c.i2c_errors),
               session_dir.c_str(), sink.monitor().marks().size(), marks_path.c_str());
  if (session.rows() == 0) {
    std::fprintf(stderr, "sinu bench: no IMU samples: nothing to calibrate\n");
    return kExitFailure;
  }
  CalibrateOptions cal;
  cal.inputs = {session_dir.string()};
  cal.out = (out / "calib.json").string();
  cal.report_dir = (out / "report").string();
  cal.quiet = o.quiet;
  if (const int rc = run_calibrate(cal); rc != kExitOk) return rc;
  const std::string target = cfg.navigation.calibration;
  if (!target.empty()) {
    fs::create_directories(fs::path(target).parent_path(), ec);
    if (!fs::copy_file(cal.out, target, fs::copy_options::overwrite_existing, ec)) {
      std::fprintf(stderr, "sinu bench: cannot write %s: %s\n", target.c_str(), ec.message().c_str());
      return kExitFailure;
    }
    std::printf("sinu fly will read %s (navigation.calibration)\n", target.c_str());
  }
  if (!sink.monitor().marks().empty()) {
    std::fprintf(stderr, "sinu bench: WARNING: the session was not still throughout (%s): repeat it, or check the "
                 "report's Allan deviation and AR fits before flying on it\n", marks_path.c_str());
  }
  return kExitOk;
}

}  // namespace

void add_bench_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand("bench", "Bench calibration on the board: record a static session, then calibrate");
  cmd->add_option("--config", o->config, "sinu.toml (default: /etc/sinu/sinu.toml if it exists)");
  cmd->add_option("--hours", o->hours, "Length of the static session [h]")->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--out", o->out, "Folder: session/, bench.json, calib.json, report/")->required();
  cmd->add_flag("--quiet", o->quiet, "No progress bar");
  o->board.add_devices(*cmd);
  o->board.add_imu(*cmd);
  o->board.add(*cmd, "--calib", [](board::FlyConfig& c) -> auto& { return c.navigation.calibration; },
               "Where to put calib.json for sinu fly (navigation.calibration)");
  cmd->add_option("--emulate", o->emulate.dataset, "Rehearsal: the sensors played by this static dataset");
  cmd->add_option("--speed", o->emulate.speed, "With --emulate: times real time (0: as fast as possible)")
      ->capture_default_str();
  cmd->callback([&action, o] { action = [o] { return run_bench(*o); }; });
}

}  // namespace sinu::cli
