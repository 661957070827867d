#pragma once
// NMEA 0183 output of the navigation solution on a serial port: an epoch of
// RMC, GGA and GST (nmea_sentences) at a configured rate, in one write, so
// an autopilot or logger can take the unit as an external GPS receiver.
#include <array>
#include <cstdint>

#include "firmware/board/nav_solution.hpp"
#include "firmware/board/outputs/nmea_sentences.hpp"
#include "hal/serial_port.hpp"

namespace sinu::board {

struct NmeaOutputConfig {
  NmeaTalker talker = NmeaTalker::GP;
  double rate_hz = 5.0;  // epochs per second of solution time (t_s)
};

struct NmeaOutputCounters {
  std::uint64_t epochs = 0;        // written in full
  std::uint64_t bytes = 0;
  std::uint64_t write_errors = 0;  // epochs the port did not take
};

class NmeaOutput {
 public:
  /// `port` must outlive the output; rate_hz must be > 0.
  NmeaOutput(hal::SerialPort& port, const NmeaOutputConfig& config);
  /// Offers the newest solution (call it with every one). Writes an epoch
  /// when one period of t_s has passed since the previous epoch's due time
  /// (the first solution is written at once; a solution time that goes
  /// backwards, a new run, starts over). Returns false only when the port
  /// failed the write (counted); the output carries on with the next epoch.
  bool offer(const NavSolution& nav);
  const NmeaOutputCounters& counters() const { return counters_; }

 private:
  hal::SerialPort& port_;
  NmeaOutputConfig config_;
  double period_s_;
  bool started_ = false;
  double due_t_s_ = 0.0;   // t_s at or after which the next epoch is written
  double last_t_s_ = 0.0;
  std::array<char, kNmeaEpochMax> text_{};
  NmeaOutputCounters counters_;
};

}  // namespace sinu::board
