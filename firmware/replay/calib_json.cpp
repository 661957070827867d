#include "firmware/replay/calib_json.hpp"

#include <array>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

namespace sinu::replay {

namespace {

constexpr std::array<const char*, 6> kAxisNames = {"ax", "ay", "az", "gx", "gy", "gz"};

bool number_at(const nlohmann::json& j, const char* key, double& out) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return false;
  out = j[key].get<double>();
  return std::isfinite(out);
}

}  // namespace

bool load_calib(const std::string& path, const CalibChoice& choice, est::SensorNoise& noise, std::string& error) {
  std::ifstream in(path);
  if (!in) {
    error = path + ": cannot open";
    return false;
  }
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    error = path + ": not valid JSON: " + e.what();
    return false;
  }
  const auto fail = [&](const std::string& key, const std::string& why) {
    error = path + ": " + key + ": " + why;
    return false;
  };
  if (!j.is_object() || !j.contains("axes") || !j["axes"].is_object()) return fail("axes", "missing");
  noise = est::SensorNoise::defaults(choice.kind);
  double rate = 40.0;
  if (!number_at(j, "sample_rate_hz", rate) && !(j.contains("denoiser") && number_at(j["denoiser"], "sample_rate_hz", rate))) {
    rate = 40.0;
  }
  if (!(rate > 0.0)) return fail("sample_rate_hz", "must be positive");
  noise.ar_sample_period_s = 1.0 / rate;
  if (choice.kind == est::NoiseModelKind::AutoRegressive &&
      (choice.ar_order < 1 || choice.ar_order > static_cast<int>(est::kMaxArOrder))) {
    return fail("ar order", "must be 1.." + std::to_string(est::kMaxArOrder) + " (the EKF's compile-time maximum)");
  }
  double white_a = 0.0, white_g = 0.0;
  int n_white_a = 0, n_white_g = 0;
  for (std::size_t i = 0; i < kAxisNames.size(); ++i) {
    const std::string key = std::string("axes.") + kAxisNames[i];
    if (!j["axes"].contains(kAxisNames[i])) return fail(key, "missing");
    const nlohmann::json& axis = j["axes"][kAxisNames[i]];
    if (choice.kind == est::NoiseModelKind::GaussMarkov) {
      if (!axis.contains("gm")) return fail(key + ".gm", "missing");
      double tau = 0.0, var = 0.0;
      if (!number_at(axis["gm"], "tau_s", tau) || !(tau > 0.0)) return fail(key + ".gm.tau_s", "missing or not positive");
      if (!number_at(axis["gm"], "variance", var) || !(var >= 0.0)) return fail(key + ".gm.variance", "missing or negative");
      noise.gm[i] = {tau, var};
    } else {
      const std::string mkey = key + ".ar." + choice.ar_method;
      if (!axis.contains("ar") || !axis["ar"].contains(choice.ar_method) || !axis["ar"][choice.ar_method].is_array()) {
        return fail(mkey, "missing");
      }
      const nlohmann::json& models = axis["ar"][choice.ar_method];
      const auto p = static_cast<std::size_t>(choice.ar_order);
      if (models.size() < p) return fail(mkey, "has no order " + std::to_string(p));
      const nlohmann::json& m = models[p - 1];
      if (!m.contains("a") || !m["a"].is_array() || m["a"].size() != p + 1) {
        return fail(mkey + "[" + std::to_string(p - 1) + "].a", "must hold 1 + " + std::to_string(p) + " coefficients");
      }
      est::ArAxis ar;
      ar.order = static_cast<Eigen::Index>(p);
      for (std::size_t k = 0; k <= p; ++k) {
        if (!m["a"][k].is_number()) return fail(mkey + ".a", "non-numeric coefficient");
        ar.a[k] = m["a"][k].get<double>();
      }
      if (std::abs(ar.a[0] - 1.0) > 1e-12) return fail(mkey + ".a[0]", "must be 1 (MATLAB convention)");
      if (!number_at(m, "variance", ar.variance) || !(ar.variance >= 0.0)) return fail(mkey + ".variance", "missing or negative");
      noise.ar[i] = ar;
    }
    double N = 0.0;
    if (axis.contains("allan") && number_at(axis["allan"], "N", N) && N > 0.0) {
      (i < 3 ? white_a : white_g) += N * N;
      ++(i < 3 ? n_white_a : n_white_g);
    }
  }
  if (n_white_a) noise.accel_white_m_s2_rthz = std::sqrt(white_a / n_white_a);
  if (n_white_g) noise.gyro_white_rad_s_rthz = std::sqrt(white_g / n_white_g);
  return true;
}

}  // namespace sinu::replay
