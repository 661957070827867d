#pragma once
// meta.json: free-form JSON object; known keys imu_rate_hz, gps_rate_hz,
// notes. Nothing in it is required to process a dataset.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "firmware/host/dataset/diagnostic.hpp"

namespace sinu::dataset {

struct Meta {
  std::optional<double> imu_rate_hz;
  std::optional<double> gps_rate_hz;
  nlohmann::json object = nlohmann::json::object();  // everything, known keys included
};

/// Reads and checks meta.json. Syntax errors carry line and column.
bool read_meta(const std::string& path, Meta& out, Diagnostic& err);
bool write_meta(const std::string& path, const Meta& meta, Diagnostic& err);

}  // namespace sinu::dataset
