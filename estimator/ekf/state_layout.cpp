#include "estimator/ekf/state_layout.hpp"

#include <algorithm>
#include <cstring>

namespace sinu::est {

bool effect_from_name(const char* name, std::size_t length, Effect& out) {
  for (std::size_t i = 0; i < kEffectCount; ++i) {
    if (std::strlen(kEffectNames[i]) == length && std::strncmp(kEffectNames[i], name, length) == 0) {
      out = static_cast<Effect>(i);
      return true;
    }
  }
  return false;
}

const char* effect_component_name(Effect e, Eigen::Index i) {
  static constexpr const char* kXyz[] = {"x", "y", "z"};
  static constexpr const char* kSymmetric[] = {"xx", "yy", "zz", "xy", "xz", "yz"};
  static constexpr const char* kOff[] = {"xy", "xz", "yx", "yz", "zx", "zy"};
  static constexpr const char* kFull[] = {"xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"};
  const Components c = spec(e).components;
  if (i < 0 || i >= component_count(c)) return "";
  switch (c) {
    case Components::One: return "";
    case Components::Xyz: return kXyz[i];
    case Components::Symmetric: return kSymmetric[i];
    case Components::OffDiagonal: return kOff[i];
    case Components::Matrix: return kFull[i];
  }
  return "";
}

StateLayout StateLayout::make(Eigen::Index order, EffectSet effects, EffectSet deferred) {
  StateLayout l;
  l.order = order < 1 ? 1 : (order > kMaxArOrder ? kMaxArOrder : order);
  Eigen::Index next = 0;
  auto take = [&next](Eigen::Index n) {
    const Slice s{next, n};
    next += n;
    return s;
  };
  l.pos = take(3);
  l.vel = take(3);
  l.att = take(3);
  l.sensor = take(kSensorAxes * l.order);
  for (std::size_t i = 0; i < kEffectCount; ++i) {
    const auto e = static_cast<Effect>(i);
    if (effects.has(e) && !deferred.has(e)) l.effect[i] = take(kEffectDims[i]);
  }
  l.dim = next;
  for (std::size_t i = 0; i < kEffectCount; ++i) {
    if (deferred.has(static_cast<Effect>(i))) l.reserved[i] = take(kEffectDims[i]);
  }
  return l;
}

bool StateLayout::has_deferred(EffectSet which) const {
  for (std::size_t i = 0; i < kEffectCount; ++i)
    if (which.has(static_cast<Effect>(i)) && reserved[i].active()) return true;
  return false;
}

void StateLayout::activate(EffectSet which) {
  for (std::size_t i = 0; i < kEffectCount; ++i) {
    if (!which.has(static_cast<Effect>(i)) || !reserved[i].active()) continue;
    effect[i] = Slice{dim, reserved[i].size};
    dim += reserved[i].size;
    reserved[i] = Slice{};
  }
  Eigen::Index next = dim;  // the rest, still reserved, after them
  for (Slice& s : reserved) {
    if (!s.active()) continue;
    s.start = next;
    next += s.size;
  }
}

}  // namespace sinu::est
