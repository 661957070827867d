#pragma once
// A dataset folder as a replay source: imu.csv rows merged with the fixes
// assembled from gps.nmea, by arrival time.
#include "firmware/dataset/csv_table.hpp"
#include "firmware/dataset/dataset_paths.hpp"
#include "firmware/dataset/imu_csv.hpp"
#include "firmware/dataset/nmea_log.hpp"
#include "firmware/replay/replay_source.hpp"

namespace sinu::replay {

class DatasetSource final : public ReplaySource {
 public:
  /// Opens imu.csv and, when present, gps.nmea. False with `error` (file:line).
  bool open(const std::string& dir, std::string& error);
  bool run(ReplayFeed& feed, std::string& error) override;
  SourceCounters counters() const override;
  std::string default_truth() const override;

 private:
  io::DatasetPaths paths_;
  // A live stream's glitches survive a replay: the navigator drops, counts and flags them.
  io::CsvReader imu_{io::kImuSchema, io::CsvLeniency{true, true}};
  io::GpsLogReader gps_;
  bool has_gps_ = false;
  std::uint64_t incomplete_rows_ = 0;
};

}  // namespace sinu::replay
