#include "firmware/board/model_file.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

namespace sinu::board {

namespace {

bool numbers(const nlohmann::json& v, std::size_t n, bool positive, std::array<double, 9>& out) {
  if (!v.is_array() || v.size() != n) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!v[i].is_number()) return false;
    out[i] = v[i].get<double>();
    if (!std::isfinite(out[i]) || (positive && !(out[i] > 0.0))) return false;
  }
  return true;
}

}  // namespace

bool read_model_file(const std::string& path, est::EffectSet& effects,
                     std::array<est::EffectPrior, est::kEffectCount>& priors, double& imu_latency_s,
                     std::string& error) {
  nlohmann::json j;
  return parse_json_file(path, j, error) && read_model_json(j, path, effects, priors, imu_latency_s, error);
}

bool parse_json_file(const std::string& path, nlohmann::json& j, std::string& error) {
  std::ifstream in(path);
  if (!in) {
    error = path + ": cannot open the model file";
    return false;
  }
  j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  return true;
}

bool read_model_json(const nlohmann::json& j, const std::string& path, est::EffectSet& effects,
                     std::array<est::EffectPrior, est::kEffectCount>& priors, double& imu_latency_s,
                     std::string& error) {
  if (j.is_discarded() || !j.is_object() || !j.contains("effects") || !j["effects"].is_object()) {
    error = path + ": not a model file (a JSON object with an \"effects\" object)";
    return false;
  }
  for (const auto& [name, v] : j["effects"].items()) {
    est::Effect e{};
    if (!est::effect_from_name(name.c_str(), name.size(), e)) {
      error = path + ": effects." + name + ": unknown effect";
      return false;
    }
    const auto n = static_cast<std::size_t>(est::kEffectDims[static_cast<std::size_t>(e)]);
    est::EffectPrior p;
    p.given = true;
    if (!v.is_object() || !v.contains("estimate") || !numbers(v["estimate"], n, false, p.value)) {
      error = path + ": effects." + name + ".estimate: expected " + std::to_string(n) + " finite numbers";
      return false;
    }
    if (!v.contains("sigma") || !numbers(v["sigma"], n, true, p.sigma)) {
      error = path + ": effects." + name + ".sigma: expected " + std::to_string(n) + " positive numbers";
      return false;
    }
    effects.add(e);
    priors[static_cast<std::size_t>(e)] = p;
  }
  if (j.contains("imu_latency_s")) {
    const auto& v = j["imu_latency_s"];
    if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0.0 || v.get<double>() > 1.0) {
      error = path + ": imu_latency_s: expected a number of seconds in 0..1";
      return false;
    }
    imu_latency_s = v.get<double>();
  }
  return true;
}

nlohmann::json model_json(const std::vector<ModelEffect>& effects, double imu_latency_s, const std::string& source) {
  nlohmann::json j;
  j["source"] = source;
  if (imu_latency_s > 0.0) j["imu_latency_s"] = imu_latency_s;
  j["effects"] = nlohmann::json::object();
  for (const ModelEffect& m : effects) {
    j["effects"][est::spec(m.effect).name] = {{"estimate", m.estimate}, {"sigma", m.sigma},
                                              {"unit", "state units (see effect_vocabulary.hpp)"}};
  }
  return j;
}

bool write_json_file(const std::string& path, const nlohmann::json& j, std::string& error) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << j.dump(2) << "\n";
    if (!out) {
      error = path + ": cannot write (" + tmp + ")";
      return false;
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    error = path + ": cannot replace it with " + tmp;
    return false;
  }
  return true;
}

bool write_model_file(const std::string& path, const std::vector<ModelEffect>& effects, double imu_latency_s,
                      const std::string& source, std::string& error) {
  return write_json_file(path, model_json(effects, imu_latency_s, source), error);
}

}  // namespace sinu::board
