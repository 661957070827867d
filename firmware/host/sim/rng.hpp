#pragma once
// Deterministic random numbers for the simulator: xoshiro256** seeded through
// splitmix64, normals by the Marsaglia polar method. Written out here (not
// <random> distributions) so a seed gives the same dataset with any standard
// library. Independent streams per purpose (trajectory, IMU noise, GPS,
// effects) keep e.g. the trajectory unchanged when effects are added.
#include <cstdint>

namespace sinu::sim {

enum class RngStream : std::uint64_t {
  Trajectory = 1,
  ImuErrorParameters = 2,
  ImuNoise = 3,
  Gps = 4,
  Effects = 5,
  Environment = 6,
  Corruption = 7,
  BenchPositions = 8,   // a multi-position bench session: headings and placement of each attitude
  UnitAccelErrors = 9,  // the unit's accelerometer scale factors and misalignment (drawn on request)
};

class Rng {
 public:
  Rng(std::uint64_t seed, RngStream stream);
  std::uint64_t next_u64();
  /// Uniform in [0, 1).
  double uniform();
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform magnitude in [lo, hi) with a random sign.
  double signed_uniform(double lo, double hi);
  /// Log-uniform in [lo, hi).
  double log_uniform(double lo, double hi);
  /// Standard normal N(0, 1).
  double normal();
  /// Integer uniform in [0, n).
  std::uint64_t below(std::uint64_t n);

 private:
  std::uint64_t s_[4]{};
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace sinu::sim
