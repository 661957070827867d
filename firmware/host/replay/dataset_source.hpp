#pragma once
// A dataset folder as a replay source: imu.csv rows merged with the fixes
// assembled from gps.nmea, by arrival time.
#include "firmware/host/dataset/csv_table.hpp"
#include "firmware/host/dataset/dataset_paths.hpp"
#include "firmware/host/dataset/imu_csv.hpp"
#include "firmware/host/dataset/imu_row_merger.hpp"
#include "firmware/host/dataset/nmea_log.hpp"
#include "firmware/host/replay/replay_source.hpp"

namespace sinu::replay {

class DatasetSource final : public ReplaySource {
 public:
  /// Opens imu.csv and, when present, gps.nmea. False with `error` (file:line).
  bool open(const std::string& dir, std::string& error);
  bool run(ReplayFeed& feed, std::string& error) override;
  SourceCounters counters() const override;
  std::string default_truth() const override;

 private:
  dataset::DatasetPaths paths_;
  // A live stream's glitches survive a replay: the navigator drops, counts and flags them.
  dataset::CsvReader imu_{dataset::kImuSchema, dataset::CsvLeniency{true, true}};
  dataset::GpsLogReader gps_;
  bool has_gps_ = false;
  std::uint64_t fixes_after_imu_ = 0;
  double first_fix_after_imu_s_ = 0.0, imu_end_s_ = 0.0;
  dataset::ImuRowMerger merger_;  // rows with part of the IMU into samples
};

}  // namespace sinu::replay
