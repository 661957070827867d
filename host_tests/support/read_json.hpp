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

/// summary.json's entry for effect `name` ({"name", "estimate", "sigma"}), or null when it has none.
inline nlohmann::json summary_effect(const nlohmann::json& summary, const std::string& name) {
  for (const auto& e : summary["effects"]) {
    if (e["name"] == name) return e;
  }
  return nullptr;
}

}  // namespace sinu::test
