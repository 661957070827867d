#include "firmware/board/effect_selection.hpp"

#include <vector>

namespace sinu::board {

namespace {
// Effects of the shared vocabulary that the EKF does not model yet.
constexpr const char* kVocabularyNotModelled[] = {"accel_misalign", "gyro_misalign",
                                                  "gyro_g_sensitivity"};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= s.size()) {
    const std::size_t end = s.find(sep, start);
    out.push_back(s.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}
}  // namespace

est::EffectSet default_effects() {
  est::EffectSet s;
  s.add(est::Effect::AccelBias);
  s.add(est::Effect::GyroBias);
  s.add(est::Effect::GpsPositionBias);
  s.add(est::Effect::GpsLatency);
  return s;
}

bool resolve_effects(const std::string& added, const std::string& removed, est::EffectSet& out, std::string& error) {
  est::EffectSet add, remove;
  if (!parse_effects(added, add, error)) return false;
  if (removed == "none" || removed == "all") {
    remove = default_effects();
  } else if (!parse_effects(removed, remove, error)) {
    error = "--without-effects" + error.substr(error.find(':'));
    return false;
  }
  out.bits = (default_effects().bits | add.bits) & ~remove.bits;
  return true;
}

bool parse_effects(const std::string& text, est::EffectSet& out, std::string& error) {
  out = {};
  if (text.empty()) return true;
  for (const std::string& name : split(text, ',')) {
    est::Effect e;
    if (est::effect_from_name(name.c_str(), name.size(), e)) {
      out.add(e);
      continue;
    }
    for (const char* v : kVocabularyNotModelled) {
      if (name == v) {
        error = "--effects: '" + name + "' is in the effect vocabulary but the EKF does not model it yet";
        return false;
      }
    }
    std::string list;
    for (const char* n : est::kEffectNames) list += std::string(list.empty() ? "" : ", ") + n;
    error = "--effects: unknown effect '" + name + "' (modelled: " + list + ")";
    return false;
  }
  return true;
}

}  // namespace sinu::board
