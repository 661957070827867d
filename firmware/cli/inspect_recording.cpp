// sinu inspect recording FILE: what a raw HAL recording holds.
#include <array>
#include <cstdio>
#include <string>

#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "hal/i2c_bus.hpp"
#include "hal/recording/recording_reader.hpp"

namespace sinu::cli {

namespace {

int inspect_recording(const std::string& file) {
  hal::rec::RecordingReader reader;
  if (!reader.open(file)) {
    std::fprintf(stderr, "%s\n", reader.message().c_str());
    return kExitFailure;
  }
  std::array<std::uint64_t, hal::rec::kKindEnd> count{}, bytes{};
  std::array<std::uint64_t, 5> i2c_status{};
  hal::TimeNs first = 0, last = 0, first_edge = 0, last_edge = 0;
  hal::rec::Record r;
  hal::rec::ReadStatus st;
  while ((st = reader.next(r)) == hal::rec::ReadStatus::Record) {
    const auto k = static_cast<std::size_t>(r.kind);
    if (reader.records() == 1) first = r.t_ns;
    last = r.t_ns;
    ++count[k];
    bytes[k] += r.payload.size();
    if ((r.kind == hal::rec::Kind::I2cRead || r.kind == hal::rec::Kind::I2cWrite) && r.payload.size() >= 3 &&
        r.payload[2] < i2c_status.size())
      ++i2c_status[r.payload[2]];
    if (r.kind == hal::rec::Kind::GpioEdge) {
      if (count[k] == 1) first_edge = r.t_ns;
      last_edge = r.t_ns;
    }
  }
  using hal::rec::Kind;
  auto n = [&](Kind k) { return static_cast<unsigned long long>(count[static_cast<std::size_t>(k)]); };
  std::printf("recording %s (format version %u)\n", file.c_str(), reader.version());
  std::printf("  records        %llu over %.3f s\n", static_cast<unsigned long long>(reader.records()),
              hal::ns_to_s(last - first));
  const unsigned long long edges = n(Kind::GpioEdge);
  std::printf("  gpio edges     %llu", edges);
  if (edges > 1) std::printf("  (%.2f Hz)", static_cast<double>(edges - 1) / hal::ns_to_s(last_edge - first_edge));
  std::printf("\n  i2c reads      %llu, writes %llu;", n(Kind::I2cRead), n(Kind::I2cWrite));
  for (std::size_t s = 1; s < i2c_status.size(); ++s)
    if (i2c_status[s] > 0)
      std::printf(" %s %llu", hal::to_string(static_cast<hal::I2cStatus>(s)), static_cast<unsigned long long>(i2c_status[s]));
  std::printf("\n  serial rx      %llu chunks, %llu bytes\n", n(Kind::SerialRx),
              static_cast<unsigned long long>(bytes[static_cast<std::size_t>(Kind::SerialRx)] - count[static_cast<std::size_t>(Kind::SerialRx)]));
  std::printf("  serial tx      %llu chunks; baud changes %llu\n", n(Kind::SerialTx), n(Kind::SerialBaud));
  if (n(Kind::EdgeTimeout) > 0) std::printf("  edge timeouts  %llu (the IMU was polled)\n", n(Kind::EdgeTimeout));
  if (reader.unknown_records() > 0)
    std::printf("  unknown kinds  %llu (skipped)\n", static_cast<unsigned long long>(reader.unknown_records()));
  if (reader.time_reversals() > 0)
    std::printf("  time reversals %llu\n", static_cast<unsigned long long>(reader.time_reversals()));
  if (st == hal::rec::ReadStatus::Truncated) {
    std::printf("  %s\n", reader.message().c_str());
    std::fprintf(stderr, "%s\n", reader.message().c_str());
  }
  if (st == hal::rec::ReadStatus::Corrupt) {
    std::fprintf(stderr, "%s\n", reader.message().c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

void add_inspect_recording_command(CLI::App& inspect, Action& action) {
  auto file = std::make_shared<std::string>();
  CLI::App* cmd = inspect.add_subcommand("recording", "Summarise a raw HAL recording");
  cmd->add_option("FILE", *file, "A raw recording (sinu record, sinu fly --record, sinu convert)")->required();
  cmd->callback([&action, file] { action = [file] { return inspect_recording(*file); }; });
}

}  // namespace sinu::cli
