// sinu record --out FILE: record the board's raw HAL traffic (IMU I2C
// transfers, GPS serial bytes, data-ready edges) without navigating, with a
// line a second on what the sensors deliver.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <string>

#include "firmware/board/board_loop.hpp"
#include "firmware/board/linux_board.hpp"
#include "firmware/cli/board_options.hpp"
#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "firmware/cli/stop_signal.hpp"

namespace sinu::cli {

namespace {

struct RecordOptions {
  BoardOptions board;
  std::string out;
  double duration_s = 0.0;
};

/// Counts what the sensors deliver and says so once a second; syncs the recording.
class SensorStatusSink final : public board::BoardSink {
 public:
  explicit SensorStatusSink(hal::rec::RecordingWriter& writer) : writer_(writer) {}
  void on_imu(const drivers::ImuSample&) override { ++samples_; }
  void on_sentence(hal::TimeNs, std::string_view) override { ++sentences_; }
  void on_fix(const drivers::GpsFix& f) override { fixes_ += f.has_position() ? 1u : 0u; }
  void on_tick(hal::TimeNs now) override {
    if (now - last_sync_ >= hal::rec::RecordingWriter::kSyncPeriodNs) {
      writer_.sync();  // at most one second lost on a crash, even when sensors go quiet
      last_sync_ = now;
    }
    if (now - last_report_ < 1'000'000'000) return;
    last_report_ = now;
    std::fprintf(stderr, "sinu record: imu samples %llu, nmea sentences %llu, fixes %llu\n",
                 static_cast<unsigned long long>(samples_), static_cast<unsigned long long>(sentences_),
                 static_cast<unsigned long long>(fixes_));
  }

 private:
  hal::rec::RecordingWriter& writer_;
  hal::TimeNs last_sync_ = 0, last_report_ = 0;
  std::uint64_t samples_ = 0, sentences_ = 0, fixes_ = 0;
};

int run_record(const RecordOptions& o) {
  drivers::Icm20948Config cfg;
  std::string error;
  if (!o.board.imu_config(cfg, error)) {
    std::fprintf(stderr, "sinu record: %s\n", error.c_str());
    return kExitUsage;
  }
  board::LinuxBoard board;
  if (!board.open(o.board.values.imu, o.board.values.gps, o.out, error)) {
    std::fprintf(stderr, "sinu record: %s\n", error.c_str());
    return kExitFailure;
  }
  install_stop_signals();
  board::BoardLoop loop(board.devices(), cfg);
  SensorStatusSink sink(*board.writer());
  loop.run(sink, &stop_requested(), static_cast<hal::TimeNs>(o.duration_s * 1e9));
  const auto& c = loop.imu().counters();
  std::fprintf(stderr, "imu: %llu samples, %llu i2c errors, %llu reinits; gps: %llu good sentences, %llu corrupt\n",
               static_cast<unsigned long long>(c.samples), static_cast<unsigned long long>(c.i2c_errors),
               static_cast<unsigned long long>(c.reinits),
               static_cast<unsigned long long>(loop.gps_counters().sentences.good),
               static_cast<unsigned long long>(loop.gps_counters().sentences.corrupt()));
  if (!board.writer()->close()) {
    std::fprintf(stderr, "sinu record: %s\n", board.writer()->error().c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

void add_record_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<RecordOptions>();
  CLI::App* cmd = app.add_subcommand("record", "Record raw HAL traffic from the board's sensors");
  cmd->add_option("--out", o->out, "Raw recording to write")->required();
  o->board.add_devices(*cmd);
  o->board.add_imu(*cmd);
  cmd->add_option("--duration", o->duration_s, "Stop after this many seconds (0: until Ctrl-C)")->check(CLI::NonNegativeNumber);
  cmd->callback([&action, o] { action = [o] { return run_record(*o); }; });
}

}  // namespace sinu::cli
