#pragma once
// `sinu fly`: the board's sensor loop feeding the navigation unit, and the
// unit's solutions going out: MAVLink to the flight controller, NMEA to an
// external-GPS input, the navigation log. Once a second a health line on
// stderr (the journal under systemd) says what the unit and its sensors are
// doing, and why when something is wrong. Nothing here allocates after
// init(); the loop does not know whether its devices are the board's (Linux)
// or an emulator's.
//
// Faults: the IMU driver retries failed transfers and re-initialises the chip
// (drivers/imu/icm20948.hpp); the loop polls when data-ready edges stop
// (board_loop.hpp); a silent or garbled GPS leaves the navigator coasting
// with growing sigmas and its GNSS-timeout flag. Each shows in the health
// line while it lasts.
#include <atomic>
#include <cstdio>
#include <string>

#include "firmware/board/board_loop.hpp"
#include "firmware/board/loop_stats.hpp"
#include "firmware/board/nav_unit.hpp"
#include "firmware/board/outputs/mavlink_output.hpp"
#include "firmware/board/outputs/nav_log.hpp"
#include "firmware/board/outputs/nmea_output.hpp"
#include "hal/recording/recording_writer.hpp"

namespace sinu::board {

/// Where solutions go; each optional (nullptr: not configured).
struct FlyOutputs {
  MavlinkOutput* mavlink = nullptr;
  NmeaOutput* nmea = nullptr;
  std::string log_path;       // the navigation log (sinu replay's nav.csv columns); "": none
  double log_period_s = 0.1;  // its rows: 10 Hz, as sinu replay's nav.csv
};

struct FlyLoopConfig {
  double health_period_s = 1.0;  // wall time between health lines; 0: none
  // The wall time of the latest data-ready edge, when edges are not stamped
  // on the wall clock (an emulated board); nullptr: they are (Linux).
  const hal::TimeNs* edge_wall_ns = nullptr;
  hal::rec::RecordingWriter* recording = nullptr;  // synced once a second
  std::FILE* health = stderr;
};

/// What the unit and its sensors did in one health period.
struct FlyHealth {
  double t_s = 0.0;
  std::uint64_t imu_samples = 0, polled = 0, i2c_errors = 0, reinits = 0;
  std::uint64_t fixes = 0, corrupt_sentences = 0;
  std::uint64_t garbage_bytes = 0;  // GPS bytes outside any sentence, or in abandoned ones
  double since_imu_s = 0.0, since_fix_s = 0.0;  // board time since the last sample / fix
};

class FlyLoop final : private BoardSink, private est::NavObserver {
 public:
  FlyLoop(const BoardDevices& devices, const drivers::Icm20948Config& imu, const FlyOutputs& outputs,
          hal::Clock& wall, const FlyLoopConfig& config);
  /// Builds the navigation unit and creates the log (its columns follow the
  /// unit's states); false with `error` (the calibration file, the log) otherwise.
  bool init(const NavUnitConfig& unit, std::string& error);
  /// Runs until the devices close (an emulation's end), `stop` is set (SIGINT,
  /// SIGTERM) or `duration_ns` > 0 has passed; then processes what the
  /// navigator still holds and flushes the log.
  /// False if writing the log failed (disk full), after the run.
  bool close_log(std::string& error);
  void run(const std::atomic<bool>* stop, hal::TimeNs duration_ns);

  const LoopStats& stats() const { return stats_; }
  const NavUnit& unit() const { return unit_; }
  const BoardLoop& board() const { return loop_; }
  std::uint64_t solutions() const { return solutions_; }
  /// Writes the health line for `h` into `buf` (no allocation); its length.
  std::size_t health_line(const FlyHealth& h, char* buf, std::size_t size) const;

 private:
  void on_imu(const drivers::ImuSample& sample) override;
  void on_sentence(hal::TimeNs, std::string_view) override {}
  void on_fix(const drivers::GpsFix& fix) override;
  void on_tick(hal::TimeNs now_ns) override;
  void on_nav(const est::NavOutput& out) override;
  void on_innovation(const est::InnovationRecord&) override {}
  void report(hal::TimeNs now_ns);

  BoardLoop loop_;
  NavUnit unit_;
  FlyOutputs outputs_;
  NavLog log_;
  bool logging_ = false;
  hal::Clock& wall_;
  FlyLoopConfig config_;
  LoopStats stats_;
  NavSolution solution_;
  std::uint64_t solutions_ = 0;
  std::uint32_t flags_ = 0;  // events since the last health line
  hal::TimeNs last_sample_ns_ = 0, last_fix_ns_ = 0, last_report_wall_ns_ = 0, last_sync_ns_ = 0;
  bool have_sample_ = false, have_fix_ = false;
  FlyHealth at_last_report_;    // counters at the previous health line
  int state_note_printed_ = 0;  // NavUnit::state_note_version() last printed
  std::uint64_t fixes_ = 0;
};

}  // namespace sinu::board
