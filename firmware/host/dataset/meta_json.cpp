#include "firmware/host/dataset/meta_json.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace sinu::dataset {

namespace {

/// 1-based line and column of a byte offset.
void locate(const std::string& text, std::size_t byte, std::size_t& line, std::size_t& column) {
  line = 1;
  column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
}

bool read_rate(const nlohmann::json& obj, const char* key, std::optional<double>& out, Diagnostic& err) {
  if (!obj.contains(key)) return true;
  const auto& v = obj.at(key);
  if (!v.is_number() || !(v.get<double>() > 0.0)) {
    err.message = std::string("key '") + key + "': expected a positive number";
    return false;
  }
  out = v.get<double>();
  return true;
}

}  // namespace

bool read_meta(const std::string& path, Meta& out, Diagnostic& err) {
  err = Diagnostic{path, 0, 0, {}};
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    err.message = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  try {
    out.object = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    locate(text, e.byte > 0 ? e.byte - 1 : 0, err.line, err.column);
    err.message = "invalid JSON";
    return false;
  }
  if (!out.object.is_object()) {
    err.message = "expected a JSON object";
    return false;
  }
  return read_rate(out.object, "imu_rate_hz", out.imu_rate_hz, err) &&
         read_rate(out.object, "gps_rate_hz", out.gps_rate_hz, err);
}

bool write_meta(const std::string& path, const Meta& meta, Diagnostic& err) {
  err = Diagnostic{path, 0, 0, {}};
  nlohmann::json obj = meta.object.is_object() ? meta.object : nlohmann::json::object();
  if (meta.imu_rate_hz) obj["imu_rate_hz"] = *meta.imu_rate_hz;
  if (meta.gps_rate_hz) obj["gps_rate_hz"] = *meta.gps_rate_hz;
  std::ofstream outf(path, std::ios::binary);
  outf << obj.dump(1) << '\n';
  if (!outf) {
    err.message = std::string("cannot write: ") + std::strerror(errno);
    return false;
  }
  return true;
}

}  // namespace sinu::dataset
