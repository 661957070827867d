#pragma once
// Mounting of a sensor on the airframe as a signed axis permutation:
// body_FRD[i] = sign[i] * sensor[axis[i]]. Board mountings in 90-degree steps
// are exactly this, and a permutation is exact in floating point, so a
// dataset converted to raw register values and back is bit-identical.
#include <array>
#include <optional>
#include <string_view>

namespace sinu::drivers {

struct AxisMap {
  std::array<int, 3> axis{0, 1, 2};
  std::array<double, 3> sign{1.0, 1.0, 1.0};

  std::array<double, 3> to_body(const std::array<double, 3>& s) const {
    return {sign[0] * s[static_cast<std::size_t>(axis[0])], sign[1] * s[static_cast<std::size_t>(axis[1])],
            sign[2] * s[static_cast<std::size_t>(axis[2])]};
  }
  std::array<double, 3> to_sensor(const std::array<double, 3>& b) const {
    std::array<double, 3> s{};
    for (std::size_t i = 0; i < 3; ++i) s[static_cast<std::size_t>(axis[i])] = sign[i] * b[i];
    return s;
  }
  /// Parses "x,-y,-z" (body x,y,z from sensor axes); nullopt unless a signed permutation.
  static std::optional<AxisMap> parse(std::string_view text);
};

/// The ICM-20948 flat, component side up, pin 1 forward-left: its axes are
/// x forward, y left, z up; FRD is x, -y, -z.
inline constexpr AxisMap kChipUpToFrd{{0, 1, 2}, {1.0, -1.0, -1.0}};
/// The AK09916 die inside the ICM-20948 has y and z opposite to the
/// accelerometer's (datasheet section 12, orientation of axes).
inline constexpr AxisMap kMagToChip{{0, 1, 2}, {1.0, -1.0, -1.0}};

}  // namespace sinu::drivers
