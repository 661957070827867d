#include "firmware/board/state_file.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "firmware/board/model_file.hpp"

namespace sinu::board {

namespace {

/// `n` finite numbers at key `key` of `j` (absent: left as they are).
bool optional_numbers(const nlohmann::json& j, const char* key, Eigen::Index n, double* out, const std::string& path,
                      std::string& error) {
  if (!j.contains(key)) return true;
  const nlohmann::json& v = j[key];
  const bool scalar = n == 1 && v.is_number();
  if (!scalar && !(v.is_array() && v.size() == static_cast<std::size_t>(n))) {
    error = path + ": " + key + ": expected " + std::to_string(n) + " number(s)";
    return false;
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    const nlohmann::json& x = scalar ? v : v[static_cast<std::size_t>(i)];
    if (!x.is_number() || !std::isfinite(x.get<double>())) {
      error = path + ": " + key + ": expected finite numbers";
      return false;
    }
    out[i] = x.get<double>();
  }
  return true;
}

/// The optional "vehicle" object: what the vehicle detector had found.
bool read_vehicle(const nlohmann::json& j, const std::string& path, est::WarmStart& w, std::string& error) {
  if (!j.contains("vehicle")) return true;
  const nlohmann::json& v = j["vehicle"];
  const std::string where = path + ": vehicle";
  if (!v.is_object() || !v.contains("guess") || !v["guess"].is_string()) {
    error = where + ": expected an object with \"guess\": \"ground\"";
    return false;
  }
  const std::string guess = v["guess"].get<std::string>();
  if (guess != "ground") {
    error = where + ".guess: \"" + guess + "\": expected \"ground\"";
    return false;
  }
  est::VehicleAxes axes;
  if (!optional_numbers(v, "lateral_b", 3, axes.lateral_b.data(), where, error) ||
      !optional_numbers(v, "vertical_b", 3, axes.vertical_b.data(), where, error))
    return false;
  // Unit vectors at right angles (to the file's 17 digits; 1e-6 leaves room for an edited one).
  if (std::abs(axes.lateral_b.norm() - 1.0) > 1e-6 || std::abs(axes.vertical_b.norm() - 1.0) > 1e-6 ||
      std::abs(axes.lateral_b.dot(axes.vertical_b)) > 1e-6) {
    error = where + ": lateral_b and vertical_b: expected two unit vectors at right angles";
    return false;
  }
  if (v.contains("on_bracket") && !v["on_bracket"].is_boolean()) {
    error = where + ".on_bracket: expected true or false";
    return false;
  }
  w.ground_vehicle = true;
  w.on_bracket = v.value("on_bracket", false);
  w.vehicle_axes = axes;
  return true;
}

}  // namespace

bool read_state_file(const std::string& path, SavedState& out, std::string& error) {
  out = {};
  est::EffectSet effects;
  double imu_latency_s = 0.0;
  nlohmann::json j;
  if (!parse_json_file(path, j, error) || !read_model_json(j, path, effects, out.warm.effects, imu_latency_s, error))
    return false;
  if (!j.contains("saved_utc_ms") || !j["saved_utc_ms"].is_number_integer()) {
    error = path + ": saved_utc_ms: expected an integer (ms since 1970-01-01 UTC); not a state file?";
    return false;
  }
  out.saved_utc_ms = j["saved_utc_ms"].get<std::int64_t>();
  est::WarmStart& w = out.warm;
  if (!optional_numbers(j, "temp_ref_degC", 1, &w.temp_ref_degC, path, error) ||
      !optional_numbers(j, "gps_bias_level_ned_m", 3, w.gps_bias_level_ned_m.data(), path, error) ||
      !optional_numbers(j, "gnss_velocity_sigma_m_s", 1, &w.gnss_velocity_sigma_m_s, path, error) ||
      !optional_numbers(j, "mag_sigma_uT", 1, &w.mag_sigma_uT, path, error) ||
      !optional_numbers(j, "gnss_white_scale", 2, w.gnss_white_scale.data(), path, error) ||
      !optional_numbers(j, "gnss_position_scale", 2, w.gnss_position_scale.data(), path, error) ||
      !read_vehicle(j, path, w, error))
    return false;
  w.given = true;
  return true;
}

bool write_state_file(const std::string& path, const SavedState& s, std::string& error) {
  const est::WarmStart& w = s.warm;
  std::vector<ModelEffect> effects;
  for (std::size_t e = 0; e < est::kEffectCount; ++e) {
    const est::EffectPrior& p = w.effects[e];
    if (!p.given) continue;
    const auto n = static_cast<std::size_t>(est::kEffectDims[e]);
    effects.push_back({static_cast<est::Effect>(e), {p.value.begin(), p.value.begin() + n},
                       {p.sigma.begin(), p.sigma.begin() + n}});
    for (double& sigma : effects.back().sigma) sigma = std::max(sigma, 1e-12);  // a held component: 0
  }
  nlohmann::json j = model_json(effects, 0.0, "sinu: the running unit's state, for a restart");
  const auto vec = [](const auto& v) { return std::vector<double>(v.data(), v.data() + v.size()); };
  j["saved_utc_ms"] = s.saved_utc_ms;
  j["temp_ref_degC"] = w.temp_ref_degC;
  j["gps_bias_level_ned_m"] = vec(w.gps_bias_level_ned_m);
  j["gnss_velocity_sigma_m_s"] = w.gnss_velocity_sigma_m_s;
  j["mag_sigma_uT"] = w.mag_sigma_uT;
  j["gnss_white_scale"] = vec(w.gnss_white_scale);
  j["gnss_position_scale"] = vec(w.gnss_position_scale);
  if (w.ground_vehicle)
    j["vehicle"] = {{"guess", "ground"},
                    {"on_bracket", w.on_bracket},
                    {"lateral_b", vec(w.vehicle_axes.lateral_b)},
                    {"vertical_b", vec(w.vehicle_axes.vertical_b)}};
  return write_json_file(path, j, error);
}

}  // namespace sinu::board
