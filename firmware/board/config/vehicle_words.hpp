#pragma once
// The words for what carries the unit, the same in sinu.toml
// (navigation.vehicle) and on the command line (--vehicle).
#include <array>
#include <cstddef>
#include <string_view>

#include "estimator/nav/navigator.hpp"

namespace sinu::board {

inline constexpr std::array<std::string_view, 3> kVehicleWords = {"air", "ground", "auto"};
inline constexpr std::array<est::VehicleKind, 3> kVehicleKinds = {est::VehicleKind::Air, est::VehicleKind::Ground,
                                                                  est::VehicleKind::Auto};

inline bool vehicle_from_word(std::string_view word, est::VehicleKind& out) {
  for (std::size_t i = 0; i < kVehicleWords.size(); ++i) {
    if (kVehicleWords[i] == word) {
      out = kVehicleKinds[i];
      return true;
    }
  }
  return false;
}

inline std::string_view vehicle_word(est::VehicleKind kind) {
  for (std::size_t i = 0; i < kVehicleKinds.size(); ++i)
    if (kVehicleKinds[i] == kind) return kVehicleWords[i];
  return "?";
}

}  // namespace sinu::board
