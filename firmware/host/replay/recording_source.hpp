#pragma once
// A raw HAL recording as a replay source: the replay back ends (hal/replay)
// drive the board's sensor loop, so the samples come out of the same
// ICM-20948 driver and NMEA stream as on the board, with HAL time stamps.
//
// The loop hands a GPS fix over once its epoch is complete (its last
// sentence, or the next epoch's first), which is after IMU samples later than
// the fix's arrival (its first sentence). A dataset replay feeds each fix
// before the first sample at or after its arrival; to feed the navigator the
// very same sequence, samples wait here in a fixed-size buffer until the
// loop's clock is kReorderWindowNs past them, and the fixes that arrived by
// a sample's time go first. A fix completed even later than that (an epoch
// spread over more than the window) is fed at once and counted.
#include <memory>

#include "estimator/util/ring_buffer.hpp"
#include "firmware/board/board_loop.hpp"
#include "firmware/host/replay/replay_source.hpp"
#include "hal/replay/replay_devices.hpp"

namespace sinu::replay {

class RecordingSource final : public ReplaySource, private board::BoardSink {
 public:
  static constexpr hal::TimeNs kReorderWindowNs = 2'000'000'000;  // a 1 Hz receiver's first epoch completes 1 s late
  static constexpr std::size_t kHeldSamples = 2048;               // 2 s at 1000 Hz
  static constexpr std::size_t kHeldFixes = 64;                   // 2 s at 25 Hz, and margin

  explicit RecordingSource(const drivers::Icm20948Config& imu) : imu_config_(imu) {}
  /// Reads the whole recording. False with `error` naming the file when it
  /// cannot be opened or is not a recording; a truncated or corrupt tail
  /// ends the replay there and is reported by note().
  bool open(const std::string& path, std::string& error);
  bool run(ReplayFeed& feed, std::string& error) override;
  void full_scale(double& accel_m_s2, double& gyro_rad_s) const override;
  SourceCounters counters() const override { return counters_; }
  std::string note() const override;

  std::uint64_t reordered_fixes() const { return reordered_fixes_; }

 private:
  void on_imu(const drivers::ImuSample& sample) override;
  void on_sentence(hal::TimeNs, std::string_view) override {}
  void on_fix(const drivers::GpsFix& fix) override;
  void on_tick(hal::TimeNs now_ns) override;
  void release_oldest();

  drivers::Icm20948Config imu_config_;
  std::string path_;
  std::unique_ptr<hal::ReplaySession> session_;
  struct Held {
    est::ImuSample sample;
    hal::TimeNs t_ns = 0;
  };
  std::unique_ptr<est::RingBuffer<Held, kHeldSamples>> held_;
  std::unique_ptr<est::RingBuffer<drivers::GpsFix, kHeldFixes>> fixes_;
  ReplayFeed* feed_ = nullptr;
  double last_fed_t_s_ = -1e300;
  SourceCounters counters_;
  std::uint64_t reordered_fixes_ = 0, imu_errors_ = 0, desyncs_ = 0;
};

}  // namespace sinu::replay
