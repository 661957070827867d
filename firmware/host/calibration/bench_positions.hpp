#pragma once
// The attitudes of a multi-position bench calibration, in the order the
// board is asked for them (`sinu bench --positions N`) and the simulator
// holds them (`sinu simulate static --positions N`): each is the body axis
// (FRD) that points up. The six faces first, ordered so that each step is a
// quarter turn; then the eight corners of a cube jig (each axis 35 deg above
// or below the horizon: they sense the misalignment, which the faces see only
// at second order); then the twelve edges (two axes 45 deg up).
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>

namespace sinu::calibration {

inline constexpr std::size_t kFaces = 6;
inline constexpr std::size_t kMaxPositions = 26;

/// The up direction of position k (0-based), before normalising: components -1, 0, +1.
inline constexpr std::array<std::array<int, 3>, kMaxPositions> kPositionUp = {{
    {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1},               // faces
    {1, 1, 1}, {1, -1, 1}, {-1, -1, 1}, {-1, 1, 1},                                     // corners
    {-1, 1, -1}, {-1, -1, -1}, {1, -1, -1}, {1, 1, -1},
    {1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {-1, 1, 0}, {0, 1, 1}, {0, -1, 1},             // edges
    {0, -1, -1}, {0, 1, -1}, {1, 0, 1}, {-1, 0, 1}, {-1, 0, -1}, {1, 0, -1},
}};

/// The unit up vector of position k in the body frame (FRD).
inline Eigen::Vector3d position_up_b(std::size_t k) {
  const auto& u = kPositionUp[k];
  return Eigen::Vector3d(u[0], u[1], u[2]).normalized();
}

/// "+x up", "-z up", "+x-y+z up".
inline std::string position_name(std::size_t k) {
  std::string s;
  const char axes[3] = {'x', 'y', 'z'};
  for (std::size_t i = 0; i < 3; ++i) {
    if (kPositionUp[k][i] == 0) continue;
    s += kPositionUp[k][i] > 0 ? '+' : '-';
    s += axes[i];
  }
  return s + " up";
}

/// What to tell a person placing the board in position k.
inline std::string position_instruction(std::size_t k) {
  static constexpr std::array<const char*, kFaces> kFaceWords = {
      "level, as mounted (z down)", "nose up (x, the front, up)",       "on its left side (y, the right, up)",
      "nose down (x down)",         "on its right side (y, the right, down)", "upside down (z up)"};
  if (k < kFaces) return position_name(k) + ": " + kFaceWords[k];
  const int n = std::abs(kPositionUp[k][0]) + std::abs(kPositionUp[k][1]) + std::abs(kPositionUp[k][2]);
  return position_name(k) + (n == 3 ? ": on a corner of the jig, these three axes 35 deg above the horizon"
                                    : ": on an edge of the jig, these two axes 45 deg above the horizon");
}

}  // namespace sinu::calibration
