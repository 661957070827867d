#pragma once
// What innovations.csv says about a model: per aiding source, the Gaussian
// negative log-likelihood of the innovations under the filter's own
// predicted sigmas, NIS per component, and the rejections. Two runs of the
// same data with different state sets are compared through the likelihood:
// the model that predicts the measurements better has the lower NLL.
// Per flight phase too, so a user sees *where* the model fails.
#include <array>
#include <cstdint>
#include <string>

#include "firmware/diagnose/flight_phase.hpp"

namespace sinu::diag {

inline constexpr std::size_t kSources = 3;
inline constexpr std::array<const char*, kSources> kSourceNames = {"gnss_position", "gnss_velocity", "magnetometer"};

struct ComponentStats {
  std::uint64_t count = 0;
  double nll = 0.0;        // sum of 0.5 (y^2 / s^2 + 2 ln s)  [ln(2 pi) terms dropped]
  double z2_sum = 0.0;     // sum of y^2 / s^2 (NIS per component; expected 1 each)
  std::uint64_t rejected = 0;
  double mean_z() const { return count ? z_sum / static_cast<double>(count) : 0.0; }
  double nis() const { return count ? z2_sum / static_cast<double>(count) : 0.0; }
  double z_sum = 0.0;      // sum of y / s (a bias shows as a mean far from 0)
  void add(double y, double s, bool accepted);
};

struct InnovationStats {
  std::array<ComponentStats, kSources> source{};
  std::array<std::array<ComponentStats, kPhaseCount>, kSources> by_phase{};
  double total_nll() const;
};

/// Reads DIR/innovations.csv (and DIR/nav.csv for the flight phases). False
/// with `error` naming the file and line otherwise.
bool read_innovation_stats(const std::string& replay_dir, InnovationStats& out, std::string& error);

}  // namespace sinu::diag
