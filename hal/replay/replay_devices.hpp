#pragma once
// Replay back ends: the HAL interfaces fed from a raw recording. The devices
// share one cursor over the records and answer in the order the board's loop
// asked during recording, so the same drivers see the same bytes:
//   - wait_rising() returns the edge or the timeout at the cursor (and sets
//     the clock to its time); serial bytes there are OtherInput; any other
//     record is one the loop did not ask for (a desync: counted, skipped);
//   - read() on the serial port returns the chunk at the cursor, or nothing;
//   - an I2C transfer must match the record at the cursor (address, register,
//     length) and gets its recorded status and bytes; a mismatch is a
//     desynchronised replay: counted, answered with I2cStatus::Io.
// The clock follows the recording: each record consumed moves it to the
// record's time (never backwards).
#include <cstdint>
#include <string>
#include <vector>

#include "hal/gpio_edge.hpp"
#include "hal/i2c_bus.hpp"
#include "hal/recording/recording_reader.hpp"
#include "hal/replay/manual_clock.hpp"
#include "hal/serial_port.hpp"

namespace sinu::hal {

class ReplaySession {
 public:
  /// Reads the whole recording. False if it cannot be opened; a truncated or
  /// corrupt tail is kept as a note (stop_message()) and replay ends there.
  bool load(const std::string& path, std::string& error);
  bool load(rec::RecordingReader& reader);
  ManualClock& clock() { return clock_; }
  I2cBus& i2c() { return i2c_; }
  SerialPort& serial() { return serial_; }
  GpioEdge& drdy() { return drdy_; }
  std::uint64_t desyncs() const { return desyncs_; }
  std::size_t records() const { return records_.size(); }
  std::size_t consumed() const { return cursor_; }
  const std::string& stop_message() const { return stop_message_; }

 private:
  struct Entry {
    rec::Kind kind;
    TimeNs t_ns;
    std::size_t offset, length;  // payload in bytes_
  };
  const Entry* at() const { return cursor_ < records_.size() ? &records_[cursor_] : nullptr; }
  const std::uint8_t* payload(const Entry& e) const { return bytes_.data() + e.offset; }
  void consume(const Entry& e);
  void skip_outputs();

  class I2c final : public I2cBus {
   public:
    explicit I2c(ReplaySession& s) : s_(s) {}
    I2cStatus read_registers(std::uint8_t address, std::uint8_t reg, std::span<std::uint8_t> data) override;
    I2cStatus write_registers(std::uint8_t address, std::uint8_t reg, std::span<const std::uint8_t> data) override;

   private:
    I2cStatus transfer(rec::Kind kind, std::uint8_t address, std::uint8_t reg, std::size_t n, std::uint8_t* out);
    ReplaySession& s_;
  };
  class Serial final : public SerialPort {
   public:
    explicit Serial(ReplaySession& s) : s_(s) {}
    bool set_baud(std::uint32_t baud) override;
    SerialResult read(std::span<std::uint8_t> out, TimeNs timeout_ns) override;
    SerialResult write(std::span<const std::uint8_t> bytes) override;

   private:
    ReplaySession& s_;
    std::size_t chunk_offset_ = 0;  // bytes of the current chunk already returned
  };
  class Drdy final : public GpioEdge {
   public:
    explicit Drdy(ReplaySession& s) : s_(s) {}
    EdgeStatus wait_rising(TimeNs timeout_ns, TimeNs& edge_time_ns) override;

   private:
    ReplaySession& s_;
  };

  std::vector<Entry> records_;
  std::vector<std::uint8_t> bytes_;
  std::size_t cursor_ = 0;
  std::uint64_t desyncs_ = 0;
  std::string stop_message_;
  ManualClock clock_;
  I2c i2c_{*this};
  Serial serial_{*this};
  Drdy drdy_{*this};
};

}  // namespace sinu::hal
