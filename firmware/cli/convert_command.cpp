// sinu convert IN OUT: a raw HAL recording -> dataset folder (replayed through
// the drivers), or a dataset folder -> raw recording (through the emulated
// ICM-20948 and an NMEA byte stream). The direction follows IN: a folder is
// a dataset, a file a recording.
#include <cstdio>
#include <filesystem>
#include <string>

#include "drivers/imu/emulated_icm20948.hpp"
#include "firmware/board/board_loop.hpp"
#include "firmware/host/convert/dataset_devices.hpp"
#include "firmware/host/convert/dataset_sink.hpp"
#include "firmware/cli/board_options.hpp"
#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "hal/recording/recording_taps.hpp"
#include "hal/replay/replay_devices.hpp"

namespace sinu::cli {

namespace {

struct ConvertOptions {
  std::string in, out;
  BoardOptions imu;
};

/// Counts what the loop delivers; the recording taps do the writing.
class CountingSink final : public board::BoardSink {
 public:
  void on_imu(const drivers::ImuSample&) override { ++samples; }
  void on_sentence(hal::TimeNs, std::string_view) override { ++sentences; }
  void on_fix(const drivers::GpsFix&) override { ++fixes; }
  std::uint64_t samples = 0, sentences = 0, fixes = 0;
};

int dataset_to_raw(const ConvertOptions& o, const drivers::Icm20948Config& cfg) {
  hal::ManualClock clock;
  drivers::EmulatedIcm20948 chip(cfg.address, cfg.mounting);
  convert::DatasetDevices data(chip, clock);
  if (!data.open(o.in)) {
    std::fprintf(stderr, "%s\n", data.error().to_string().c_str());
    return kExitFailure;
  }
  // The driver starts (probe, reset, configure) in the second before the first sample.
  constexpr hal::TimeNs kStartUpNs = 1'000'000'000;
  clock.advance_to_ns(data.first_time_ns() - kStartUpNs);
  hal::rec::RecordingWriter writer;
  if (!writer.open(o.out)) {
    std::fprintf(stderr, "sinu convert: %s\n", writer.error().c_str());
    return kExitFailure;
  }
  hal::rec::RecordingI2cBus i2c(chip, writer, clock);
  hal::rec::RecordingSerialPort serial(data, writer, clock);
  hal::rec::RecordingGpioEdge drdy(data, writer);
  board::BoardLoop loop({drdy, i2c, serial, clock}, cfg);
  CountingSink sink;
  loop.run(sink);
  if (!data.error().message.empty()) {
    std::fprintf(stderr, "%s\n", data.error().to_string().c_str());
    return kExitFailure;
  }
  if (!writer.close()) {
    std::fprintf(stderr, "sinu convert: %s\n", writer.error().c_str());
    return kExitFailure;
  }
  std::printf("%s: %llu imu samples (%llu rows without a gyro folded in, %llu before any accelerometer left out) -> "
              "%llu samples, %llu sentences, %llu fixes; %llu records\n",
              o.out.c_str(), static_cast<unsigned long long>(data.samples()),
              static_cast<unsigned long long>(data.folded_rows()), static_cast<unsigned long long>(data.skipped_rows()),
              static_cast<unsigned long long>(sink.samples),
              static_cast<unsigned long long>(sink.sentences), static_cast<unsigned long long>(sink.fixes),
              static_cast<unsigned long long>(writer.records()));
  return kExitOk;
}

int raw_to_dataset(const ConvertOptions& o, const drivers::Icm20948Config& cfg) {
  hal::ReplaySession session;
  std::string error;
  if (!session.load(o.in, error)) {
    std::fprintf(stderr, "sinu convert: %s\n", error.c_str());
    return kExitFailure;
  }
  if (!session.stop_message().empty()) std::fprintf(stderr, "sinu convert: note: %s\n", session.stop_message().c_str());
  convert::DatasetSink sink;
  if (!sink.open(o.out)) {
    std::fprintf(stderr, "sinu convert: %s\n", sink.error().c_str());
    return kExitFailure;
  }
  board::BoardLoop loop({session.drdy(), session.i2c(), session.serial(), session.clock()}, cfg);
  loop.run(sink);
  if (!sink.close()) {
    std::fprintf(stderr, "sinu convert: %s\n", sink.error().c_str());
    return kExitFailure;
  }
  const auto& c = loop.imu().counters();
  std::printf("%s: %llu imu rows, %llu sentences, %llu fixes; imu errors %llu, replay desyncs %llu\n", o.out.c_str(),
              static_cast<unsigned long long>(sink.rows()), static_cast<unsigned long long>(sink.sentences()),
              static_cast<unsigned long long>(sink.fixes()), static_cast<unsigned long long>(c.i2c_errors),
              static_cast<unsigned long long>(session.desyncs()));
  if (session.desyncs() > 0)
    std::fprintf(stderr, "sinu convert: warning: %llu records did not match the driver's requests (other --mounting or "
                         "driver settings than when recorded?)\n",
                 static_cast<unsigned long long>(session.desyncs()));
  return kExitOk;
}

int convert(const ConvertOptions& o) {
  drivers::Icm20948Config cfg;
  std::string error;
  if (!o.imu.imu_config(cfg, error)) {
    std::fprintf(stderr, "sinu convert: %s\n", error.c_str());
    return kExitUsage;
  }
  if (std::filesystem::is_directory(o.in)) return dataset_to_raw(o, cfg);
  if (!std::filesystem::exists(o.in)) {
    std::fprintf(stderr, "sinu convert: %s: no such file or folder\n", o.in.c_str());
    return kExitFailure;
  }
  return raw_to_dataset(o, cfg);
}

}  // namespace

void add_convert_command(CLI::App& app, Action& action) {
  auto opts = std::make_shared<ConvertOptions>();
  CLI::App* cmd = app.add_subcommand("convert", "Convert a raw HAL recording to a dataset folder and back");
  cmd->add_option("IN", opts->in, "A raw recording (file) or a dataset folder")->required();
  cmd->add_option("OUT", opts->out, "The dataset folder or raw recording to write")->required();
  opts->imu.add_imu(*cmd);
  cmd->callback([&action, opts] { action = [opts] { return convert(*opts); }; });
}

}  // namespace sinu::cli
