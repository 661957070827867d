// sinu record --out FILE: record the board's raw HAL traffic (IMU I2C
// transfers, GPS serial bytes, data-ready edges) without navigating.
// sinu fly [--record FILE]: the board's sensor loop feeding navigation.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <string>

#include "firmware/board/board_loop.hpp"
#include "firmware/cli/board_devices.hpp"
#include "firmware/cli/board_options.hpp"
#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"

namespace sinu::cli {

namespace {

std::atomic<bool> g_stop{false};
extern "C" void on_signal(int) { g_stop = true; }

struct BoardRunOptions {
  DeviceOptions devices;
  ImuOptions imu;
  std::string record;
  double duration_s = 0.0;
  bool navigate = false;
};

/// Counts and, once per second, reports what the sensors deliver. The
/// navigation seam: `sinu fly` hands samples and fixes to the estimator
/// here once issue #6 (INS/EKF) lands; until then it says so and prints no
/// navigation output.
class SensorStatusSink final : public board::BoardSink {
 public:
  SensorStatusSink(hal::rec::RecordingWriter* writer, bool navigate) : writer_(writer), navigate_(navigate) {}
  void on_imu(const drivers::ImuSample&) override { ++samples_; }  // issue #6: estimator.predict(sample)
  void on_sentence(hal::TimeNs, std::string_view) override { ++sentences_; }
  void on_fix(const drivers::GpsFix& f) override { fixes_ += f.has_position() ? 1u : 0u; }  // issue #6: estimator.update(fix)
  void on_tick(hal::TimeNs now) override {
    if (writer_ && now - last_sync_ >= hal::rec::RecordingWriter::kSyncPeriodNs) {
      writer_->sync();  // at most one second lost on a crash, even when sensors go quiet
      last_sync_ = now;
    }
    if (now - last_report_ < 1'000'000'000) return;
    last_report_ = now;
    std::fprintf(stderr, "imu samples %llu, nmea sentences %llu, fixes %llu%s\n",
                 static_cast<unsigned long long>(samples_), static_cast<unsigned long long>(sentences_),
                 static_cast<unsigned long long>(fixes_), navigate_ ? "; navigation: pending issue #6" : "");
  }

 private:
  hal::rec::RecordingWriter* writer_;
  bool navigate_;
  hal::TimeNs last_sync_ = 0, last_report_ = 0;
  std::uint64_t samples_ = 0, sentences_ = 0, fixes_ = 0;
};

int run_board(const BoardRunOptions& o) {
  drivers::Icm20948Config cfg;
  std::string error;
  if (!o.imu.to_config(cfg, error)) {
    std::fprintf(stderr, "sinu: %s\n", error.c_str());
    return kExitUsage;
  }
  LinuxBoard board;
  if (!board.open(o.devices, o.record, error)) {
    std::fprintf(stderr, "sinu: %s\n", error.c_str());
    return kExitFailure;
  }
  if (o.navigate)
    std::fprintf(stderr, "sinu fly: the INS/EKF (issue #6) is not in this build: sensors only, no navigation output\n");
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  board::BoardLoop loop(board.devices(), cfg);
  SensorStatusSink sink(board.writer(), o.navigate);
  loop.run(sink, &g_stop, static_cast<hal::TimeNs>(o.duration_s * 1e9));
  const auto& c = loop.imu().counters();
  std::fprintf(stderr, "imu: %llu samples, %llu i2c errors, %llu reinits; gps: %llu good sentences, %llu corrupt\n",
               static_cast<unsigned long long>(c.samples), static_cast<unsigned long long>(c.i2c_errors),
               static_cast<unsigned long long>(c.reinits),
               static_cast<unsigned long long>(loop.gps_counters().sentences.good),
               static_cast<unsigned long long>(loop.gps_counters().sentences.corrupt()));
  if (auto* w = board.writer(); w && !w->close()) {
    std::fprintf(stderr, "sinu: %s\n", w->error().c_str());
    return kExitFailure;
  }
  return kExitOk;
}

void add_board_options(CLI::App& cmd, BoardRunOptions& o) {
  o.devices.add_to(cmd);
  o.imu.add_to(cmd);
  cmd.add_option("--duration", o.duration_s, "Stop after this many seconds (0: until Ctrl-C)")->check(CLI::NonNegativeNumber);
}

}  // namespace

void add_record_command(CLI::App& app, Action& action) {
  auto opts = std::make_shared<BoardRunOptions>();
  CLI::App* cmd = app.add_subcommand("record", "Record raw HAL traffic from the board's sensors");
  cmd->add_option("--out", opts->record, "Raw recording to write")->required();
  add_board_options(*cmd, *opts);
  cmd->callback([&action, opts] { action = [opts] { return run_board(*opts); }; });
}

void add_fly_command(CLI::App& app, Action& action) {
  auto opts = std::make_shared<BoardRunOptions>();
  opts->navigate = true;
  CLI::App* cmd = app.add_subcommand("fly", "Run the navigation unit on the companion computer");
  cmd->add_option("--record", opts->record, "Also record raw HAL traffic to this file");
  add_board_options(*cmd, *opts);
  cmd->callback([&action, opts] { action = [opts] { return run_board(*opts); }; });
}

}  // namespace sinu::cli
