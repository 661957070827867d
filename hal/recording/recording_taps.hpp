#pragma once
// Decorators that pass every call through to a real (or emulated) device and
// append what happened to a raw recording, stamped with the HAL clock. Wrap
// the board's devices in these to record a flight (`sinu record`, `sinu fly
// --record`); the replay back ends (hal/replay/) play the file back.
#include <cstdint>

#include "hal/gpio_edge.hpp"
#include "hal/i2c_bus.hpp"
#include "hal/recording/recording_writer.hpp"
#include "hal/serial_port.hpp"

namespace sinu::hal::rec {

class RecordingI2cBus final : public I2cBus {
 public:
  RecordingI2cBus(I2cBus& inner, RecordingWriter& writer, Clock& clock) : inner_(inner), writer_(writer), clock_(clock) {}
  I2cStatus read_registers(std::uint8_t address, std::uint8_t reg, std::span<std::uint8_t> data) override;
  I2cStatus write_registers(std::uint8_t address, std::uint8_t reg, std::span<const std::uint8_t> data) override;

 private:
  I2cBus& inner_;
  RecordingWriter& writer_;
  Clock& clock_;
};

class RecordingSerialPort final : public SerialPort {
 public:
  RecordingSerialPort(SerialPort& inner, RecordingWriter& writer, Clock& clock, std::uint8_t port = 0)
      : inner_(inner), writer_(writer), clock_(clock), port_(port) {}
  bool set_baud(std::uint32_t baud) override;
  SerialResult read(std::span<std::uint8_t> out, TimeNs timeout_ns) override;
  SerialResult write(std::span<const std::uint8_t> bytes) override;

 private:
  SerialPort& inner_;
  RecordingWriter& writer_;
  Clock& clock_;
  std::uint8_t port_;
};

class RecordingGpioEdge final : public GpioEdge {
 public:
  RecordingGpioEdge(GpioEdge& inner, RecordingWriter& writer, std::uint8_t line = 0)
      : inner_(inner), writer_(writer), line_(line) {}
  EdgeStatus wait_rising(TimeNs timeout_ns, TimeNs& edge_time_ns) override;

 private:
  GpioEdge& inner_;
  RecordingWriter& writer_;
  std::uint8_t line_;
};

}  // namespace sinu::hal::rec
