#include "firmware/host/sim/effects.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

namespace sinu::sim {

namespace {

using nlohmann::json;

// A shape/value error for key `key` of `file`.
bool fail(dataset::Diagnostic& err, const std::string& file, std::string_view key, const std::string& why) {
  err.file = file;
  err.line = 0;
  err.column = 0;
  err.message = fmt::format("effect '{}': {}", key, why);
  return false;
}

bool finite_number(const json& v, double& out) {
  if (!v.is_number()) return false;
  out = v.get<double>();
  return std::isfinite(out);
}

bool read_vector(const json& v, Eigen::Vector3d& out) {
  if (!v.is_array() || v.size() != 3) return false;
  for (std::size_t i = 0; i < 3; ++i)
    if (!finite_number(v[i], out[static_cast<Eigen::Index>(i)])) return false;
  return true;
}

bool read_matrix(const json& v, Eigen::Matrix3d& out) {
  if (!v.is_array() || v.size() != 3) return false;
  for (std::size_t r = 0; r < 3; ++r) {
    Eigen::Vector3d row;
    if (!read_vector(v[r], row)) return false;
    out.row(static_cast<Eigen::Index>(r)) = row.transpose();
  }
  return true;
}

json vector_json(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }
json matrix_json(const Eigen::Matrix3d& m) {
  json rows = json::array();
  for (Eigen::Index r = 0; r < 3; ++r) rows.push_back(vector_json(m.row(r).transpose()));
  return rows;
}

constexpr const char* kVectorShape = "expected an array of 3 finite numbers";
constexpr const char* kMatrixShape = "expected a 3x3 array of rows of finite numbers";

bool vector_effect(const json& v, const std::string& file, std::string_view key, std::optional<Eigen::Vector3d>& out,
                   dataset::Diagnostic& err) {
  Eigen::Vector3d x;
  if (!read_vector(v, x)) return fail(err, file, key, kVectorShape);
  out = x;
  return true;
}

bool misalign_effect(const json& v, const std::string& file, std::string_view key,
                     std::optional<Eigen::Matrix3d>& out, dataset::Diagnostic& err) {
  Eigen::Matrix3d m;
  if (!read_matrix(v, m)) return fail(err, file, key, kMatrixShape);
  if (m.diagonal().cwiseAbs().maxCoeff() != 0.0)
    return fail(err, file, key, "diagonal must be 0 (per-axis scale belongs to *_scale)");
  if (m.cwiseAbs().maxCoeff() > 0.2) return fail(err, file, key, "misalignment above 0.2 rad is not a small angle");
  out = m;
  return true;
}

}  // namespace

std::size_t Effects::count() const {
  return static_cast<std::size_t>(accel_scale_ppm.has_value()) + gyro_scale_ppm.has_value() +
         accel_misalign_rad.has_value() + gyro_misalign_rad.has_value() + lever_arm_b_m.has_value() +
         gps_latency_s.has_value() + accel_temp_bias_m_s2_per_degC.has_value() +
         gyro_temp_bias_rad_s_per_degC.has_value() + mag_hard_iron_uT.has_value() + mag_soft_iron.has_value() +
         gyro_g_sensitivity_rad_s_per_m_s2.has_value();
}

bool parse_effects(const json& j, const std::string& file, Effects& out, dataset::Diagnostic& err) {
  out = Effects{};
  if (!j.is_object()) return fail(err, file, "(top level)", "expected a JSON object of effect names");
  for (const auto& [key, v] : j.items()) {
    bool ok = true;
    if (key == "accel_scale") ok = vector_effect(v, file, key, out.accel_scale_ppm, err);
    else if (key == "gyro_scale") ok = vector_effect(v, file, key, out.gyro_scale_ppm, err);
    else if (key == "accel_misalign") ok = misalign_effect(v, file, key, out.accel_misalign_rad, err);
    else if (key == "gyro_misalign") ok = misalign_effect(v, file, key, out.gyro_misalign_rad, err);
    else if (key == "lever_arm") ok = vector_effect(v, file, key, out.lever_arm_b_m, err);
    else if (key == "accel_temp_bias") ok = vector_effect(v, file, key, out.accel_temp_bias_m_s2_per_degC, err);
    else if (key == "gyro_temp_bias") ok = vector_effect(v, file, key, out.gyro_temp_bias_rad_s_per_degC, err);
    else if (key == "mag_hard_iron") ok = vector_effect(v, file, key, out.mag_hard_iron_uT, err);
    else if (key == "gps_latency") {
      double s = 0.0;
      if (!finite_number(v, s)) return fail(err, file, key, "expected a finite number of seconds");
      if (s < 0.0 || s > 1.0) return fail(err, file, key, fmt::format("{} s is outside 0..1 s", s));
      out.gps_latency_s = s;
    } else if (key == "mag_soft_iron" || key == "gyro_g_sensitivity") {
      Eigen::Matrix3d m;
      if (!read_matrix(v, m)) return fail(err, file, key, kMatrixShape);
      (key == "mag_soft_iron" ? out.mag_soft_iron : out.gyro_g_sensitivity_rad_s_per_m_s2) = m;
    } else {
      return fail(err, file, key, "unknown effect (known: accel_scale, gyro_scale, accel_misalign, gyro_misalign, "
                                  "lever_arm, gps_latency, accel_temp_bias, gyro_temp_bias, mag_hard_iron, "
                                  "mag_soft_iron, gyro_g_sensitivity)");
    }
    if (!ok) return false;
  }
  return true;
}

bool read_effects_file(const std::string& path, Effects& out, dataset::Diagnostic& err) {
  std::ifstream in(path);
  if (!in) {
    err = {path, 0, 0, "cannot open effects file"};
    return false;
  }
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) {
    err = {path, 0, 0, fmt::format("not valid JSON: {}", e.what())};
    return false;
  }
  return parse_effects(j, path, out, err);
}

json effects_to_json(const Effects& e) {
  json j = json::object();
  if (e.accel_scale_ppm) j["accel_scale"] = vector_json(*e.accel_scale_ppm);
  if (e.gyro_scale_ppm) j["gyro_scale"] = vector_json(*e.gyro_scale_ppm);
  if (e.accel_misalign_rad) j["accel_misalign"] = matrix_json(*e.accel_misalign_rad);
  if (e.gyro_misalign_rad) j["gyro_misalign"] = matrix_json(*e.gyro_misalign_rad);
  if (e.lever_arm_b_m) j["lever_arm"] = vector_json(*e.lever_arm_b_m);
  if (e.gps_latency_s) j["gps_latency"] = *e.gps_latency_s;
  if (e.accel_temp_bias_m_s2_per_degC) j["accel_temp_bias"] = vector_json(*e.accel_temp_bias_m_s2_per_degC);
  if (e.gyro_temp_bias_rad_s_per_degC) j["gyro_temp_bias"] = vector_json(*e.gyro_temp_bias_rad_s_per_degC);
  if (e.mag_hard_iron_uT) j["mag_hard_iron"] = vector_json(*e.mag_hard_iron_uT);
  if (e.mag_soft_iron) j["mag_soft_iron"] = matrix_json(*e.mag_soft_iron);
  if (e.gyro_g_sensitivity_rad_s_per_m_s2) j["gyro_g_sensitivity"] = matrix_json(*e.gyro_g_sensitivity_rad_s_per_m_s2);
  return j;
}

namespace {

Eigen::Vector3d signed_vector(Rng& rng, double lo, double hi) {
  return {rng.signed_uniform(lo, hi), rng.signed_uniform(lo, hi), rng.signed_uniform(lo, hi)};
}

Eigen::Matrix3d off_diagonal(Rng& rng, double lo, double hi) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (Eigen::Index r = 0; r < 3; ++r)
    for (Eigen::Index c = 0; c < 3; ++c)
      if (r != c) m(r, c) = rng.signed_uniform(lo, hi);
  return m;
}

// Magnitudes "large enough to matter": each is several times what the default
// stochastic model or a 5 Hz GPS would hide (docs/simulation.md).
void draw_one(std::size_t index, Rng& rng, Effects& e) {
  constexpr double kMrad = 1e-3;
  constexpr double kDeg = std::numbers::pi / 180.0;
  switch (index) {
    case 0: e.accel_scale_ppm = signed_vector(rng, 5000.0, 15000.0); break;
    case 1: e.gyro_scale_ppm = signed_vector(rng, 10000.0, 30000.0); break;
    case 2: e.accel_misalign_rad = off_diagonal(rng, 5.0 * kMrad, 15.0 * kMrad); break;
    case 3: e.gyro_misalign_rad = off_diagonal(rng, 5.0 * kMrad, 15.0 * kMrad); break;
    case 4: e.lever_arm_b_m = signed_vector(rng, 0.4, 1.0); break;
    case 5: e.gps_latency_s = rng.uniform(0.1, 0.3); break;
    case 6: e.accel_temp_bias_m_s2_per_degC = signed_vector(rng, 3e-3, 8e-3); break;
    case 7: e.gyro_temp_bias_rad_s_per_degC = signed_vector(rng, 0.01 * kDeg, 0.03 * kDeg); break;
    case 8: e.mag_hard_iron_uT = signed_vector(rng, 10.0, 30.0); break;
    case 9: {
      const Eigen::Matrix3d p = off_diagonal(rng, 0.03, 0.08);
      Eigen::Matrix3d s = Eigen::Matrix3d::Identity() + 0.5 * (p + p.transpose());
      for (Eigen::Index i = 0; i < 3; ++i) s(i, i) += rng.signed_uniform(0.05, 0.15);
      e.mag_soft_iron = s;
      break;
    }
    default: {
      // 0.05-0.15 deg/s per g on the diagonal, a third of it across axes.
      const double lo = 0.05 * kDeg / 9.80665, hi = 0.15 * kDeg / 9.80665;
      Eigen::Matrix3d g = off_diagonal(rng, lo / 3.0, hi / 3.0);
      for (Eigen::Index i = 0; i < 3; ++i) g(i, i) = rng.signed_uniform(lo, hi);
      e.gyro_g_sensitivity_rad_s_per_m_s2 = g;
      break;
    }
  }
}

}  // namespace

Effects draw_random_effects(std::size_t k, Rng& rng) {
  std::array<std::size_t, kEffectNames.size()> order{};
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  for (std::size_t i = order.size() - 1; i > 0; --i) std::swap(order[i], order[rng.below(i + 1)]);
  Effects e;
  for (std::size_t i = 0; i < std::min(k, order.size()); ++i) draw_one(order[i], rng, e);
  return e;
}

}  // namespace sinu::sim
