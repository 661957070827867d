#pragma once
// A JSON file a test's run wrote (summary.json, calib.json, diagnosis.json, ...).
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace sinu::test {

inline nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

}  // namespace sinu::test
