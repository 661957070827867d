#pragma once
// Where `sinu replay` gets its samples: a dataset folder (imu.csv, gps.nmea)
// or a raw HAL recording run through the board loop and the drivers
// (HAL -> drivers -> estimator). A dataset feeds each GPS fix before the
// first IMU sample at or after its arrival; a recording feeds it when the
// board completed its epoch, as `sinu fly` did. Within the navigator's
// horizon the order makes no difference, so a recording converted from a
// dataset (`sinu convert`) replays to the same bits as the dataset it
// converts back to.
#include <cstdint>
#include <memory>
#include <string>

#include "drivers/gps/gps_fix.hpp"
#include "drivers/imu/icm20948.hpp"
#include "estimator/ins/imu_sample.hpp"

namespace sinu::replay {

class ReplayFeed {
 public:
  virtual ~ReplayFeed() = default;
  virtual void on_fix(const drivers::GpsFix& fix) = 0;
  virtual void on_imu(const est::ImuSample& sample) = 0;
};

struct SourceCounters {
  std::uint64_t incomplete_rows = 0;    // imu.csv rows with a gyro reading before any accelerometer one (left out)
  std::uint64_t rows_folded = 0;        // imu.csv rows without a gyro reading, folded into the next sample
  std::uint64_t accel_interpolated = 0;  // samples whose specific force is interpolated between rows (dataset/imu_row_merger.hpp)
  std::uint64_t accel_held = 0;         // samples whose specific force an earlier row gave, held
  std::uint64_t corrupt_sentences = 0;  // NMEA sentences failing checksum/fields, plus skipped gps.nmea lines
  std::uint64_t time_anomalies = 0;     // imu.csv rows whose time did not increase (passed on, dropped there)
  std::uint64_t non_finite_rows = 0;    // imu.csv rows with a NaN/inf value (passed on, dropped there)
  std::string first_anomaly;            // file:line:column of the first of either ("" if none)
  std::uint64_t fixes_after_imu = 0;    // GNSS fixes arriving after the last IMU sample (never used)
  double first_fix_after_imu_s = 0.0, imu_end_s = 0.0;  // valid when fixes_after_imu > 0
};

class ReplaySource {
 public:
  virtual ~ReplaySource() = default;
  /// Feeds everything, in order, once. False with `error` (naming the file,
  /// and line where known) on a read error.
  virtual bool run(ReplayFeed& feed, std::string& error) = 0;
  /// The IMU's full scales where the source knows them (a recording: the
  /// driver's configuration); a dataset leaves the caller's values.
  virtual void full_scale(double& /*accel_m_s2*/, double& /*gyro_rad_s*/) const {}
  virtual SourceCounters counters() const = 0;
  /// The truth.csv used when none is given ("" for none).
  virtual std::string default_truth() const { return {}; }
  /// What the user should know after run() (a truncated recording, ...); "" if nothing.
  virtual std::string note() const { return {}; }
};

/// `in` is a dataset folder or a raw recording file (recognised by its
/// header); `imu` configures the ICM-20948 driver for a recording. nullptr
/// with `error` naming `in` when it is neither or cannot be read.
std::unique_ptr<ReplaySource> open_replay_source(const std::string& in, const drivers::Icm20948Config& imu,
                                                 std::string& error);

}  // namespace sinu::replay
