#include "hal/recording/recording_taps.hpp"

#include <array>

namespace sinu::hal::rec {

I2cStatus RecordingI2cBus::read_registers(std::uint8_t address, std::uint8_t reg, std::span<std::uint8_t> data) {
  const I2cStatus s = inner_.read_registers(address, reg, data);
  const std::array<std::uint8_t, 3> head{address, reg, static_cast<std::uint8_t>(s)};
  writer_.append(Kind::I2cRead, clock_.now_ns(), head, data);
  return s;
}

I2cStatus RecordingI2cBus::write_registers(std::uint8_t address, std::uint8_t reg, std::span<const std::uint8_t> data) {
  const I2cStatus s = inner_.write_registers(address, reg, data);
  const std::array<std::uint8_t, 3> head{address, reg, static_cast<std::uint8_t>(s)};
  writer_.append(Kind::I2cWrite, clock_.now_ns(), head, data);
  return s;
}

bool RecordingSerialPort::set_baud(std::uint32_t baud) {
  const bool ok = inner_.set_baud(baud);
  const std::array<std::uint8_t, 5> payload{port_, static_cast<std::uint8_t>(baud), static_cast<std::uint8_t>(baud >> 8),
                                            static_cast<std::uint8_t>(baud >> 16), static_cast<std::uint8_t>(baud >> 24)};
  if (ok) writer_.append(Kind::SerialBaud, clock_.now_ns(), payload);
  return ok;
}

SerialResult RecordingSerialPort::read(std::span<std::uint8_t> out, TimeNs timeout_ns) {
  const SerialResult r = inner_.read(out, timeout_ns);
  if (r.status == SerialStatus::Ok && r.bytes > 0) {
    const std::array<std::uint8_t, 1> head{port_};
    // Chunks longer than a record's payload are split, same time stamp.
    for (std::size_t done = 0; done < r.bytes; done += kMaxPayload - 1) {
      const std::size_t n = std::min(kMaxPayload - 1, r.bytes - done);
      writer_.append(Kind::SerialRx, r.time_ns, head, out.subspan(done, n));
    }
  }
  return r;
}

SerialResult RecordingSerialPort::write(std::span<const std::uint8_t> bytes) {
  const SerialResult r = inner_.write(bytes);
  const std::array<std::uint8_t, 1> head{port_};
  for (std::size_t done = 0; done < r.bytes; done += kMaxPayload - 1) {
    const std::size_t n = std::min(kMaxPayload - 1, r.bytes - done);
    writer_.append(Kind::SerialTx, clock_.now_ns(), head, bytes.subspan(done, n));
  }
  return r;
}

EdgeStatus RecordingGpioEdge::wait_rising(TimeNs timeout_ns, TimeNs& edge_time_ns) {
  const EdgeStatus s = inner_.wait_rising(timeout_ns, edge_time_ns);
  // Edges and timeouts: what the loop does next depends on which it was (a
  // timeout makes it poll the IMU). OtherInput needs no record: the serial
  // bytes it announced are recorded when read.
  const std::array<std::uint8_t, 1> payload{line_};
  if (s == EdgeStatus::Edge) writer_.append(Kind::GpioEdge, edge_time_ns, payload);
  // An error is a timeout to the loop (it polls), so it replays as one.
  if (s == EdgeStatus::Timeout || s == EdgeStatus::Error) writer_.append(Kind::EdgeTimeout, edge_time_ns, payload);
  return s;
}

}  // namespace sinu::hal::rec
