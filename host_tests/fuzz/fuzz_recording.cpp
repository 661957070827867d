// libFuzzer: arbitrary bytes as a raw recording: the reader, then a replay
// of whatever it accepted through the board loop (ICM-20948 driver, NMEA).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "firmware/board/board_loop.hpp"
#include "hal/recording/recording_reader.hpp"
#include "hal/replay/replay_devices.hpp"

namespace {
class NullSink final : public sinu::board::BoardSink {
 public:
  void on_imu(const sinu::drivers::ImuSample&) override {}
  void on_sentence(sinu::hal::TimeNs, std::string_view) override {}
  void on_fix(const sinu::drivers::GpsFix&) override {}
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sinu::hal::rec::RecordingReader reader;
  if (!reader.open_bytes({data, size})) return 0;
  sinu::hal::ReplaySession session;
  session.load(reader);
  if (reader.records() > 0 && session.records() != reader.records()) std::abort();
  sinu::board::BoardLoop loop({session.drdy(), session.i2c(), session.serial(), session.clock()}, {});
  NullSink sink;
  loop.run(sink);
  // The loop must consume the whole recording: nothing hangs, nothing is left.
  if (session.consumed() != session.records()) std::abort();
  return 0;
}
