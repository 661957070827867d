#pragma once
// The board's sensor loop, the same on the companion computer, in a replay
// and in a conversion: wait for the IMU's data-ready edge (or GPS bytes),
// read the sample, then drain the GPS serial port through the NMEA stream.
// Everything leaves through a BoardSink with HAL time stamps; nothing here
// knows where the devices are (Linux, replay, emulator).
//
// Without edges (the INT line broke, the GPIO failed) the loop falls back to
// polling: after a wait times out it asks the IMU whether it has a new
// sample, and waits half a sample period before asking again, until edges
// come back. Polled samples carry the poll's time (up to that half period
// late); they are counted (Icm20948Counters::polled).
#include <atomic>
#include <cstdint>
#include <string_view>

#include "drivers/gps/nmea_stream.hpp"
#include "drivers/imu/icm20948.hpp"
#include "hal/clock.hpp"
#include "hal/gpio_edge.hpp"
#include "hal/i2c_bus.hpp"
#include "hal/serial_port.hpp"

namespace sinu::board {

class BoardSink {
 public:
  virtual ~BoardSink() = default;
  virtual void on_imu(const drivers::ImuSample& sample) = 0;
  /// A framed NMEA sentence (as received, valid or not) and when it arrived.
  virtual void on_sentence(hal::TimeNs arrival_ns, std::string_view sentence) = 0;
  virtual void on_fix(const drivers::GpsFix& fix) = 0;
  /// Called once per loop turn (edge or timeout) with the current time.
  virtual void on_tick(hal::TimeNs) {}
};

struct BoardDevices {
  hal::GpioEdge& drdy;
  hal::I2cBus& i2c;
  hal::SerialPort& gps;
  hal::Clock& clock;
};

struct BoardCounters {
  std::uint64_t edges = 0, edge_timeouts = 0, edge_errors = 0;
  std::uint64_t polling_starts = 0;  // times the loop fell back to polling
  std::uint64_t serial_wakeups = 0;  // waits ended by GPS bytes
  std::uint64_t serial_bytes = 0, serial_errors = 0;
};

class BoardLoop {
 public:
  static constexpr hal::TimeNs kEdgeTimeoutNs = 100'000'000;  // 4 IMU periods at 40 Hz

  BoardLoop(const BoardDevices& devices, const drivers::Icm20948Config& imu_config);
  /// Runs until the data-ready source closes (end of a replay), `stop` is set,
  /// or `duration_ns` (> 0) has passed since the start.
  void run(BoardSink& sink, const std::atomic<bool>* stop = nullptr, hal::TimeNs duration_ns = 0);
  const drivers::Icm20948& imu() const { return imu_; }
  drivers::NmeaStreamCounters gps_counters() const { return nmea_.counters(); }
  const BoardCounters& counters() const { return counters_; }
  bool polling() const { return polling_; }

 private:
  void drain_serial(BoardSink& sink);
  void poll_imu(BoardSink& sink, hal::TimeNs now_ns);

  BoardDevices dev_;
  drivers::Icm20948 imu_;
  drivers::NmeaStream nmea_;
  BoardCounters counters_;
  hal::TimeNs poll_period_ns_;
  bool polling_ = false;
};

}  // namespace sinu::board
