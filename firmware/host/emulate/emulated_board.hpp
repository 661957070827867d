#pragma once
// `sinu fly --emulate DATASET`: the board's devices played by a dataset, so
// the real fly loop runs on the host unchanged (hardware in the loop):
//   - the ICM-20948 emulator behind a fake I2C bus, loaded with each imu.csv
//     row at its time, and a fake data-ready line that rises then;
//   - the GPS bytes of gps.nmea written, each line at its arrival time, into
//     a pseudo-terminal that the loop reads through the Linux serial back end;
//   - the board's clock is the dataset's time, so every time stamp is the
//     one the dataset gives; with --speed X the emulator also waits on the
//     wall clock, so the loop runs in real time (X = 1) or X times faster
//     (0: as fast as it can).
// Faults at given dataset times rehearse what the board must survive: the
// I2C bus stops answering, GPS garbage, data-ready edges lost.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "drivers/imu/emulated_icm20948.hpp"
#include "firmware/board/board_loop.hpp"
#include "firmware/board/recording_devices.hpp"
#include "firmware/host/convert/dataset_devices.hpp"
#include "hal/linux/monotonic_clock.hpp"
#include "hal/linux/termios_serial.hpp"
#include "hal/replay/manual_clock.hpp"

namespace sinu::emulate {

enum class FaultKind : std::uint8_t { I2cStop, GpsGarbage, DrdyLost };

struct EmulatedFault {
  FaultKind kind = FaultKind::I2cStop;
  double start_s = 0.0;     // dataset time t
  double duration_s = 0.0;
};

/// "i2c-stop:START:DURATION,gps-garbage:START:DURATION,drdy-lost:START:DURATION".
bool parse_faults(const std::string& text, std::vector<EmulatedFault>& out, std::string& error);

struct EmulateOptions {
  std::string dataset;
  double speed = 1.0;  // times real time; 0: as fast as possible
  std::vector<EmulatedFault> faults;
};

struct EmulatorCounters {
  std::uint64_t edges = 0, edges_lost = 0, gps_lines = 0, garbage_lines = 0, i2c_stops = 0;
};

class EmulatedBoard final : public hal::GpioEdge {  // its own data-ready line
 public:
  EmulatedBoard();
  ~EmulatedBoard() override;
  /// Opens the dataset and the pty; `record_path` non-empty: records the
  /// traffic as the board would. False with `error` otherwise.
  bool open(const EmulateOptions& options, const drivers::Icm20948Config& imu, const std::string& record_path,
            std::string& error);
  board::BoardDevices devices();
  hal::rec::RecordingWriter* writer() { return recording_.writer(); }
  /// The wall time the latest edge was raised (loop time is measured from it).
  const hal::TimeNs* edge_wall_ns() const { return &edge_wall_ns_; }
  hal::Clock& wall_clock() { return wall_; }
  const std::string& pty_path() const { return pty_path_; }
  const EmulatorCounters& counters() const { return counters_; }
  /// A read error in the dataset ("" if none).
  std::string error() const;

 private:
  hal::EdgeStatus wait_rising(hal::TimeNs timeout_ns, hal::TimeNs& edge_time_ns) override;
  bool in_fault(FaultKind kind, hal::TimeNs t_ns) const;
  void pace(hal::TimeNs t_ns);
  bool send_gps_line();

  EmulateOptions options_;
  hal::ManualClock clock_;
  hal::MonotonicClock wall_;
  std::unique_ptr<drivers::EmulatedIcm20948> chip_;
  std::unique_ptr<convert::DatasetDevices> data_;
  hal::TermiosSerialPort serial_;  // the pty's slave side: what the loop reads
  int master_fd_ = -1, probe_fd_ = -1;
  std::string pty_path_;
  hal::TimeNs t0_ns_ = 0, wall0_ns_ = 0, edge_wall_ns_ = 0;
  bool bus_dead_ = false;
  std::uint32_t garbage_state_ = 0x2545F491u;
  EmulatorCounters counters_;
  board::RecordingDevices recording_;
};

}  // namespace sinu::emulate
