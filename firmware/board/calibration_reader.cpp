#include "firmware/board/calibration_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "estimator/wavelet/denoiser_select.hpp"

namespace sinu::board {

namespace {

constexpr std::array<const char*, 6> kAxisNames = {"ax", "ay", "az", "gx", "gy", "gz"};

bool number_at(const nlohmann::json& j, const char* key, double& out) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return false;
  out = j[key].get<double>();
  return std::isfinite(out);
}

// The slow wander the bias states must follow: the smallest random walk K
// whose Allan deviation K sqrt(tau/3) stays above the measured one for every
// cluster time from kMinTau on (minutes: longer than the GM/AR correlation
// times and the periodic components). The deviation's own minimum (B) is not
// used: with a periodic error it can sit at a second or less.
constexpr double kMinTau = 100.0;  // [s]
double bias_walk_from_allan(const nlohmann::json& axis) {
  if (!axis.contains("allan")) return 0.0;
  const nlohmann::json& a = axis["allan"];
  if (!a.contains("adev") || !a.contains("tau_s") || !a["adev"].is_array() || !a["tau_s"].is_array() ||
      a["adev"].size() != a["tau_s"].size()) {
    return 0.0;
  }
  double K = 0.0;
  for (std::size_t k = 0; k < a["tau_s"].size(); ++k) {
    if (!a["tau_s"][k].is_number() || !a["adev"][k].is_number()) return 0.0;
    const double tau = a["tau_s"][k].get<double>(), adev = a["adev"][k].get<double>();
    if (tau >= kMinTau && std::isfinite(adev)) K = std::max(K, adev * std::sqrt(3.0 / tau));
  }
  return K;
}

// denoiser.detail_sigma.<axis>[level] x denoiser.keep_details_above_sigma.
bool read_detail_thresholds(const nlohmann::json& d, DenoiserSpec& spec, std::string& key, std::string& why) {
  if (!d.contains("detail_sigma")) return true;
  key = "denoiser.keep_details_above_sigma";
  if (!number_at(d, "keep_details_above_sigma", spec.keep_above_sigma) || !(spec.keep_above_sigma > 0.0)) {
    why = "missing or not positive (detail_sigma needs it)";
    return false;
  }
  for (std::size_t i = 0; i < kAxisNames.size(); ++i) {
    key = std::string("denoiser.detail_sigma.") + kAxisNames[i];
    const nlohmann::json& s = d["detail_sigma"];
    if (!s.is_object() || !s.contains(kAxisNames[i]) || !s[kAxisNames[i]].is_array() ||
        s[kAxisNames[i]].size() != static_cast<std::size_t>(spec.levels)) {
      why = "must be an array of " + std::to_string(spec.levels) + " sigmas, one per level";
      return false;
    }
    for (std::size_t j = 0; j < static_cast<std::size_t>(spec.levels); ++j) {
      const nlohmann::json& v = s[kAxisNames[i]][j];
      if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0.0) {
        why = "level " + std::to_string(j + 1) + ": not a finite sigma >= 0";
        return false;
      }
      spec.keep_above[i][j] = spec.keep_above_sigma * v.get<double>();
    }
  }
  return true;
}

}  // namespace

bool parse_denoiser(const std::string& text, DenoiserSpec& out, std::string& error) {
  out = DenoiserSpec{};
  if (text == "none") return true;
  const auto colon = text.find(':');
  const std::string name = text.substr(0, colon);
  int levels = est::wavelet::kDefaultLevels;
  if (colon != std::string::npos) {
    const std::string lv = text.substr(colon + 1);
    if (lv.size() != 1 || lv[0] < '1' || lv[0] > '0' + est::wavelet::kMaxLevels) {
      error = "denoiser '" + text + "': levels must be 1.." + std::to_string(est::wavelet::kMaxLevels);
      return false;
    }
    levels = lv[0] - '0';
  }
  if (!est::wavelet::parse_wavelet(name)) {
    error = "denoiser '" + text + "': unknown wavelet '" + name + "' (none, haar, db2, db4, cdf53, cdf97)";
    return false;
  }
  out.wavelet = true;
  out.name = name;
  out.levels = levels;
  return true;
}

bool load_calib(const std::string& path, const CalibChoice& choice, est::SensorNoise& noise, DenoiserSpec& denoiser,
                std::string& error) {
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
  denoiser = DenoiserSpec{};
  if (j.contains("denoiser") && j["denoiser"].is_object() && j["denoiser"].contains("wavelet") &&
      j["denoiser"]["wavelet"].is_string()) {
    double levels = 0.0;
    if (!number_at(j["denoiser"], "levels", levels)) return fail("denoiser.levels", "missing");
    std::string why;
    if (!parse_denoiser(j["denoiser"]["wavelet"].get<std::string>() + ":" + std::to_string(static_cast<int>(levels)),
                        denoiser, why)) {
      return fail("denoiser", why);
    }
    std::string key;
    if (!read_detail_thresholds(j["denoiser"], denoiser, key, why)) return fail(key, why);
  }
  noise.ar_sample_period_s = 1.0 / rate;
  // The AR models at the rate their Allan deviation fits best (sinu calibrate's
  // ar_model_rate, issue 14): stepped every k-th IMU sample by the EKF.
  bool use_model_rate = false;
  if (choice.kind == est::NoiseModelKind::AutoRegressive && choice.ar_rate == "model" && j.contains("ar_model_rate") &&
      j["ar_model_rate"].is_object()) {
    double model_rate = 0.0;
    if (!number_at(j["ar_model_rate"], "rate_hz", model_rate) || !(model_rate > 0.0))
      return fail("ar_model_rate.rate_hz", "missing or not positive");
    if (!j["ar_model_rate"].contains("axes") || !j["ar_model_rate"]["axes"].is_object())
      return fail("ar_model_rate.axes", "missing");
    noise.ar_sample_period_s = 1.0 / model_rate;
    use_model_rate = true;
  } else if (choice.ar_rate != "model" && choice.ar_rate != "imu") {
    return fail("ar rate", "must be model or imu, not '" + choice.ar_rate + "'");
  }
  if (choice.kind == est::NoiseModelKind::AutoRegressive &&
      (choice.ar_order < 1 || choice.ar_order > static_cast<int>(est::kMaxArOrder))) {
    return fail("ar order", "must be 1.." + std::to_string(est::kMaxArOrder) + " (the EKF's compile-time maximum)");
  }
  double white_a = 0.0, white_g = 0.0, walk_a = 0.0, walk_g = 0.0;
  int n_white_a = 0, n_white_g = 0, n_walk_a = 0, n_walk_g = 0;
  for (std::size_t i = 0; i < kAxisNames.size(); ++i) {
    const std::string key = std::string("axes.") + kAxisNames[i];
    if (!j["axes"].contains(kAxisNames[i])) return fail(key, "missing");
    const nlohmann::json& axis = j["axes"][kAxisNames[i]];
    if (choice.kind == est::NoiseModelKind::GaussMarkov) {
      if (!axis.contains("gm")) return fail(key + ".gm", "missing");
      double tau = 0.0, var = 0.0;
      const nlohmann::json& gm = axis["gm"];
      if (gm.contains("decays") && gm["decays"] == false && gm.contains("tau_s") && gm["tau_s"].is_null()) {
        // The bench's autocorrelation never fell to 1/e (a warm-up's drift): a
        // constant of that variance for this session, which the bias states'
        // walk (the Allan rate random walk) carries beyond.
        tau = std::numeric_limits<double>::infinity();
      } else if (!number_at(gm, "tau_s", tau) || !(tau > 0.0)) {
        return fail(key + ".gm.tau_s", "missing or not positive");
      }
      if (!number_at(gm, "variance", var) || !(var >= 0.0)) return fail(key + ".gm.variance", "missing or negative");
      noise.gm[i] = {tau, var};
    } else {
      // The AR at the model rate when calib.json chose one and the user did not ask for the IMU rate's.
      const bool at_model_rate = use_model_rate;
      const nlohmann::json& fits = at_model_rate ? j["ar_model_rate"]["axes"][kAxisNames[i]] : axis;
      const std::string mkey = (at_model_rate ? "ar_model_rate.axes." + std::string(kAxisNames[i]) : key) + ".ar." +
                               choice.ar_method;
      if (!fits.contains("ar") || !fits["ar"].contains(choice.ar_method) || !fits["ar"][choice.ar_method].is_array()) {
        return fail(mkey, "missing");
      }
      const nlohmann::json& models = fits["ar"][choice.ar_method];
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
    const double K = bias_walk_from_allan(axis);
    if (K > 0.0) {
      (i < 3 ? walk_a : walk_g) += K * K;
      ++(i < 3 ? n_walk_a : n_walk_g);
    }
  }
  if (n_white_a) noise.accel_white_m_s2_rthz = std::sqrt(white_a / n_white_a);
  if (n_white_g) noise.gyro_white_rad_s_rthz = std::sqrt(white_g / n_white_g);
  if (n_walk_a) noise.accel_bias_walk = std::sqrt(walk_a / n_walk_a);
  if (n_walk_g) noise.gyro_bias_walk = std::sqrt(walk_g / n_walk_g);
  return true;
}

bool load_accel_correction(const std::string& path, AccelCorrection& out, std::string& error) {
  out = AccelCorrection{};
  std::ifstream in(path);
  if (!in) {
    error = path + ": cannot open";
    return false;
  }
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) {
    error = path + ": not valid JSON";
    return false;
  }
  if (!j.is_object() || !j.contains("six_position")) return true;
  const nlohmann::json& s = j["six_position"];
  const auto fail = [&](const std::string& key, const std::string& why) {
    error = path + ": six_position." + key + ": " + why;
    return false;
  };
  const auto vector3 = [&](const char* key, Eigen::Vector3d& v) {
    if (!s.contains(key) || !s[key].is_array() || s[key].size() != 3) return false;
    for (std::size_t i = 0; i < 3; ++i) {
      if (!s[key][i].is_number()) return false;
      v[static_cast<Eigen::Index>(i)] = s[key][i].get<double>();
    }
    return v.allFinite();
  };
  if (!s.is_object()) return fail("(section)", "not an object");
  Eigen::Vector3d scale_ppm, bias;
  if (!vector3("accel_scale", scale_ppm)) return fail("accel_scale", "expected 3 finite numbers [ppm]");
  if (scale_ppm.cwiseAbs().maxCoeff() > 1e5) return fail("accel_scale", "above 10 % (100000 ppm): not a scale factor");
  if (!vector3("accel_bias", bias)) return fail("accel_bias", "expected 3 finite numbers [m/s^2]");
  Eigen::Matrix3d M;
  if (!s.contains("accel_misalign") || !s["accel_misalign"].is_array() || s["accel_misalign"].size() != 3)
    return fail("accel_misalign", "expected a 3x3 array of rows [rad]");
  for (std::size_t r = 0; r < 3; ++r) {
    const nlohmann::json& row = s["accel_misalign"][r];
    if (!row.is_array() || row.size() != 3) return fail("accel_misalign", "expected a 3x3 array of rows [rad]");
    for (std::size_t c = 0; c < 3; ++c) {
      if (!row[c].is_number()) return fail("accel_misalign", "expected a 3x3 array of rows [rad]");
      M(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = row[c].get<double>();
    }
  }
  if (!M.allFinite() || M.diagonal().cwiseAbs().maxCoeff() != 0.0 || M.cwiseAbs().maxCoeff() > 0.2)
    return fail("accel_misalign", "must be finite, zero on the diagonal and at most 0.2 rad");
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  S.diagonal() += scale_ppm * 1e-6;
  out.gain_inverse = (S * (Eigen::Matrix3d::Identity() + M)).inverse();
  out.bias_m_s2 = bias;
  out.present = true;
  return true;
}

}  // namespace sinu::board
