#pragma once
// The files of a dataset folder (dataset-format.md).
#include <filesystem>
#include <string>

namespace sinu::dataset {

struct DatasetPaths {
  std::filesystem::path dir;
  std::string imu() const { return (dir / "imu.csv").string(); }
  std::string gps() const { return (dir / "gps.nmea").string(); }
  std::string truth() const { return (dir / "truth.csv").string(); }
  std::string meta() const { return (dir / "meta.json").string(); }
  bool has_gps() const { return std::filesystem::exists(dir / "gps.nmea"); }
  bool has_truth() const { return std::filesystem::exists(dir / "truth.csv"); }
  bool has_meta() const { return std::filesystem::exists(dir / "meta.json"); }
};

}  // namespace sinu::dataset
