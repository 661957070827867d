#pragma once
// A raw HAL recording as a replay source: the replay back ends (hal/replay)
// drive the board's sensor loop, so the samples come out of the same
// ICM-20948 driver and NMEA stream as on the board, with HAL time stamps,
// and go to the navigator in the order the board gave them: each GPS fix
// when its epoch was complete (its last sentence read), as `sinu fly` feeds
// it. A replay of what the board recorded is therefore what the board
// computed, bit for bit. A fix completed later than the navigator's horizon
// after its time of validity (the first epoch of a 1 Hz receiver, closed only
// by the next one) is late there as it was on the board, and counted.
#include <memory>

#include "firmware/board/board_loop.hpp"
#include "firmware/host/replay/replay_source.hpp"
#include "hal/replay/replay_devices.hpp"

namespace sinu::replay {

class RecordingSource final : public ReplaySource, private board::BoardSink {
 public:
  explicit RecordingSource(const drivers::Icm20948Config& imu) : imu_config_(imu) {}
  /// Reads the whole recording. False with `error` naming the file when it
  /// cannot be opened or is not a recording; a truncated or corrupt tail
  /// ends the replay there and is reported by note().
  bool open(const std::string& path, std::string& error);
  bool run(ReplayFeed& feed, std::string& error) override;
  void full_scale(double& accel_m_s2, double& gyro_rad_s) const override;
  SourceCounters counters() const override { return counters_; }
  std::string note() const override;

 private:
  void on_imu(const drivers::ImuSample& sample) override;
  void on_sentence(hal::TimeNs, std::string_view) override {}
  void on_fix(const drivers::GpsFix& fix) override { feed_->on_fix(fix); }

  drivers::Icm20948Config imu_config_;
  std::string path_;
  std::unique_ptr<hal::ReplaySession> session_;
  ReplayFeed* feed_ = nullptr;
  SourceCounters counters_;
  std::uint64_t imu_errors_ = 0, desyncs_ = 0;
};

}  // namespace sinu::replay
