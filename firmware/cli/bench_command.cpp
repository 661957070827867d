// sinu bench [--config sinu.toml] --hours H --out DIR
// sinu bench [--config sinu.toml] --positions N [--hold-s S] --out DIR
// Bench calibration on the board: records a static session through the
// drivers (DIR/session: imu.csv, gps.nmea) with a progress bar and ETA,
// warns at once and marks the data (DIR/bench.json) if the board moves or
// the temperature steps, then runs `sinu calibrate` on it (DIR/calib.json,
// DIR/report/) and puts calib.json where the configuration says `sinu fly`
// reads it (navigation.calibration). With --positions N it asks for each
// position of a multi-position calibration in turn (the six faces, then
// tilted ones), waits until the board is still there and holds it `hold_s`
// with a progress bar, and calibrates the whole recording the same way.
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
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
#include "firmware/host/calibration/bench_positions.hpp"
#include "firmware/host/calibration/face_sequencer.hpp"
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
  std::size_t positions = 1;   // > 1: a multi-position calibration
  double hold_s = 60.0;
  double latitude_deg = NAN, height_m = NAN;
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

/// Multi-position: asks for each position on stderr, follows the board
/// through them (face_sequencer.hpp) and stops the loop when all are held.
class PositionsSink final : public board::BoardSink {
 public:
  PositionsSink(convert::DatasetSink& session, std::size_t positions, double hold_s, bool quiet)
      : session_(session), seq_(positions, [&] {
          calibration::FaceSequencerConfig c;
          c.hold_s = hold_s;
          return c;
        }()),
        positions_(positions), quiet_(quiet) {
    ask();
  }
  void on_imu(const drivers::ImuSample& s) override {
    session_.on_imu(s);
    if (stop_requested()) done_ = true;
    if (seq_.finished()) return;
    const double t = hal::ns_to_s(s.t_ns);
    switch (seq_.add(t, s.specific_force_b_m_s2, s.angular_rate_b_rad_s)) {
      case calibration::FaceEvent::HoldStarted:
        std::fprintf(stderr, "sinu bench: still with %s: hold it\n", seq_.attitude().c_str());
        bar_ = std::make_unique<calibration::ProgressBar>(
            "  " + seq_.attitude(), seq_.config().hold_s, !quiet_);
        break;
      case calibration::FaceEvent::Moved:
        if (bar_) bar_->finish();
        bar_.reset();
        std::fprintf(stderr, "sinu bench: moved before the position was held %.0f s: hold it still again\n",
                     seq_.config().hold_s);
        break;
      case calibration::FaceEvent::AlreadyHeld:
        std::fprintf(stderr, "sinu bench: %s is held already: turn the board\n", seq_.attitude().c_str());
        break;
      case calibration::FaceEvent::Held: {
        if (bar_) bar_->finish();
        bar_.reset();
        const calibration::HeldFace& f = seq_.faces().back();
        std::fprintf(stderr, "sinu bench: position %zu/%zu held: %s%s\n", seq_.faces().size(), positions_,
                     f.attitude.c_str(),
                     calibration::position_name(f.asked) == f.attitude
                         ? ""
                         : (" (asked for " + calibration::position_name(f.asked) + ": also fine, any new attitude counts)").c_str());
        if (seq_.finished()) done_ = true;
        else ask();
        break;
      }
      case calibration::FaceEvent::None:
        if (bar_) bar_->update(seq_.held_s());
        break;
    }
  }
  void on_sentence(hal::TimeNs t, std::string_view sentence) override { session_.on_sentence(t, sentence); }
  void on_fix(const drivers::GpsFix& f) override { session_.on_fix(f); }
  const calibration::FaceSequencer& sequencer() const { return seq_; }
  const std::atomic<bool>* done() const { return &done_; }

 private:
  void ask() {
    std::fprintf(stderr, "sinu bench: position %zu/%zu: place the board %s, and hold it still\n",
                 seq_.faces().size() + 1, positions_, calibration::position_instruction(seq_.next()).c_str());
  }
  convert::DatasetSink& session_;
  calibration::FaceSequencer seq_;
  std::size_t positions_;
  bool quiet_;
  std::unique_ptr<calibration::ProgressBar> bar_;
  std::atomic<bool> done_{false};
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

/// `sinu calibrate` on DIR/session, then calib.json where `sinu fly` reads it.
int calibrate_and_install(const BenchOptions& o, const board::FlyConfig& cfg, const std::filesystem::path& out) {
  namespace fs = std::filesystem;
  CalibrateOptions cal;
  cal.inputs = {(out / "session").string()};
  cal.out = (out / "calib.json").string();
  cal.report_dir = (out / "report").string();
  cal.quiet = o.quiet;
  cal.latitude_deg = o.latitude_deg;
  cal.height_m = o.height_m;
  if (const int rc = run_calibrate(cal); rc != kExitOk) return rc;
  const std::string target = cfg.navigation.calibration;
  if (!target.empty()) {
    std::error_code ec;
    fs::create_directories(fs::path(target).parent_path(), ec);
    if (!fs::copy_file(cal.out, target, fs::copy_options::overwrite_existing, ec)) {
      std::fprintf(stderr, "sinu bench: cannot write %s: %s\n", target.c_str(), ec.message().c_str());
      return kExitFailure;
    }
    std::printf("sinu fly will read %s (navigation.calibration)\n", target.c_str());
  }
  return kExitOk;
}

/// The multi-position session: every position asked for and held, then calibrated.
int run_positions(const BenchOptions& o, const board::FlyConfig& cfg, const drivers::Icm20948Config& imu,
                  BoardSession& board_session, convert::DatasetSink& session, const std::filesystem::path& out) {
  PositionsSink sink(session, o.positions, o.hold_s, o.quiet);
  install_stop_signals();
  board::BoardLoop loop(board_session.devices(), imu);
  loop.run(sink, sink.done());
  if (!session.close()) {
    std::fprintf(stderr, "sinu bench: %s\n", session.error().c_str());
    return kExitFailure;
  }
  if (!board_session.error().empty()) {
    std::fprintf(stderr, "sinu bench: %s\n", board_session.error().c_str());
    return kExitFailure;
  }
  nlohmann::json faces = nlohmann::json::array();
  for (const calibration::HeldFace& f : sink.sequencer().faces()) {
    faces.push_back({{"asked", calibration::position_name(f.asked)}, {"held", f.attitude},
                     {"up_b", {f.up_b.x(), f.up_b.y(), f.up_b.z()}}, {"start_t", f.t_start_s}, {"end_t", f.t_end_s}});
  }
  const auto& c = loop.imu().counters();
  const std::string marks_path = (out / "bench.json").string();
  std::ofstream marks(marks_path);
  marks << nlohmann::json{{"positions", o.positions}, {"hold_s", o.hold_s}, {"imu_samples", c.samples},
                          {"held", faces}}.dump(2)
        << "\n";
  if (!marks) {
    std::fprintf(stderr, "sinu bench: %s: write failed\n", marks_path.c_str());
    return kExitFailure;
  }
  const std::size_t held = sink.sequencer().faces().size();
  std::fprintf(stderr, "sinu bench: %llu samples (%llu I2C errors) in %s; %zu of %zu positions held (%s)\n",
               static_cast<unsigned long long>(c.samples), static_cast<unsigned long long>(c.i2c_errors),
               (out / "session").c_str(), held, o.positions, marks_path.c_str());
  if (held < o.positions) {
    std::fprintf(stderr, "sinu bench: the session ended with %zu of %zu positions held: nothing calibrated; repeat "
                 "it\n", held, o.positions);
    return kExitFailure;
  }
  return calibrate_and_install(o, cfg, out);
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
  if (o.positions > 1) return run_positions(o, cfg, imu, board_session, session, out);
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
  if (const int rc = calibrate_and_install(o, cfg, out); rc != kExitOk) return rc;
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
  auto* hours = cmd->add_option("--hours", o->hours, "Length of the static session [h]")
                    ->capture_default_str()
                    ->check(CLI::PositiveNumber);
  auto* positions =
      cmd->add_option("--positions", o->positions,
                      "Multi-position calibration: ask for N positions in turn (6: the six faces; 7..26: then tilted "
                      "on a jig's corners and edges), hold each --hold-s")
          ->check(CLI::Range(std::size_t{6}, calibration::kMaxPositions));
  positions->excludes(hours);
  cmd->add_option("--hold-s", o->hold_s, "With --positions: hold each position still this long [s]")
      ->capture_default_str()
      ->check(CLI::Range(10.0, 86400.0));
  cmd->add_option("--latitude", o->latitude_deg, "With --positions: the bench's latitude [deg] (local gravity)")
      ->check(CLI::Range(-90.0, 90.0));
  cmd->add_option("--height", o->height_m, "With --positions: the bench's ellipsoidal height [m]")
      ->check(CLI::Range(-500.0, 9000.0));
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
