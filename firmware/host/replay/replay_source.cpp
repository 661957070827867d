#include "firmware/host/replay/replay_source.hpp"

#include <filesystem>

#include "firmware/host/replay/dataset_source.hpp"
#include "firmware/host/replay/recording_source.hpp"

namespace sinu::replay {

std::unique_ptr<ReplaySource> open_replay_source(const std::string& in, const drivers::Icm20948Config& imu,
                                                 std::string& error) {
  std::error_code ec;
  if (std::filesystem::is_directory(in, ec)) {
    auto dataset = std::make_unique<DatasetSource>();
    if (!dataset->open(in, error)) return nullptr;
    return dataset;
  }
  if (!std::filesystem::exists(in, ec)) {
    error = in + ": no such dataset folder (imu.csv, gps.nmea, ...) or raw recording file";
    return nullptr;
  }
  auto recording = std::make_unique<RecordingSource>(imu);  // the reader checks the header
  if (!recording->open(in, error)) return nullptr;
  return recording;
}

}  // namespace sinu::replay
