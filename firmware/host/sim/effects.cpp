#include "firmware/host/sim/effects.hpp"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "firmware/host/sim/effects/effect_list.hpp"

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

std::string known_names() {
  std::string out;
  for (const std::string_view n : kEffectNames) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

}  // namespace

std::size_t Effects::count() const {
  std::size_t n = 0;
  for_each_sim_effect([&]<class E>() { n += (this->*E::member).has_value() ? 1u : 0u; });
  return n;
}

bool parse_effects(const json& j, const std::string& file, Effects& out, dataset::Diagnostic& err) {
  out = Effects{};
  if (!j.is_object()) return fail(err, file, "(top level)", "expected a JSON object of effect names");
  for (const auto& [key, v] : j.items()) {
    bool known = false, ok = true;
    std::string why;
    for_each_sim_effect([&]<class E>() {
      if (known || key != E::name) return;
      known = true;
      typename E::Value value;
      ok = E::parse(v, value, why);
      if (ok) out.*E::member = value;
    });
    if (!known) return fail(err, file, key, "unknown effect (known: " + known_names() + ")");
    if (!ok) return fail(err, file, key, why);
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
  for_each_sim_effect([&]<class E>() {
    if (const auto& v = e.*E::member) j[E::name] = E::to_json(*v);
  });
  return j;
}

// Magnitudes "large enough to matter": each is several times what the default
// stochastic model or a 5 Hz GPS would hide (docs/simulation.md; each effect's draw()).
Effects draw_random_effects(std::size_t k, Rng& rng) {
  std::array<std::size_t, kEffectNames.size()> order{};
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  for (std::size_t i = order.size() - 1; i > 0; --i) std::swap(order[i], order[rng.below(i + 1)]);
  Effects e;
  for (std::size_t i = 0; i < std::min(k, order.size()); ++i) {
    std::size_t index = 0;
    for_each_sim_effect([&]<class E>() {
      if (index++ == order[i]) e.*E::member = E::draw(rng);
    });
  }
  return e;
}

void draw_unit_accel_errors(Rng& rng, Effects& e) {
  // ICM-20948 datasheet: sensitivity tolerance +-0.5 % at the component, cross-axis
  // sensitivity +-2 %; soldered on a board and packaged, 1-1.5 % and 10-20 mrad.
  constexpr double kScalePpm = 15000.0, kMisalign_rad = 15e-3;
  Eigen::Vector3d s;
  for (Eigen::Index i = 0; i < 3; ++i) s[i] = rng.uniform(-kScalePpm, kScalePpm);
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (Eigen::Index r = 0; r < 3; ++r)
    for (Eigen::Index c = 0; c < 3; ++c)
      if (r != c) m(r, c) = rng.uniform(-kMisalign_rad, kMisalign_rad);
  if (!e.accel_scale_ppm) e.accel_scale_ppm = s;
  if (!e.accel_misalign_rad) e.accel_misalign_rad = m;
}

effects::SensorEffects sensor_effects(const Effects& e) {
  effects::SensorEffects s;
  for_each_sim_effect([&]<class E>() {
    if (const auto& v = e.*E::member) E::apply(*v, s);
  });
  return s;
}

}  // namespace sinu::sim
