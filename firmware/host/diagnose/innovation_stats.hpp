#pragma once
// What the innovations say about a model: per aiding source, the Gaussian
// negative log-likelihood of the innovations under the filter's own
// predicted sigmas, NIS per component, and the rejections. Two runs of the
// same data with different state sets are compared through the likelihood:
// the model that predicts the measurements better has the lower NLL.
// Per flight phase too, so a user sees *where* the model fails.
#include <array>
#include <cstdint>

#include "firmware/host/diagnose/flight_phase.hpp"
#include "firmware/host/replay/replay_runner.hpp"

namespace sinu::diagnose {

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
  double lag_sum = 0.0;    // sum of z_t z_{t-1}, consecutive innovations of one component
  void add(double y, double s, bool accepted);
  /// Lag-1 autocorrelation of z: the innovations' whiteness (0 when white, as a
  /// right model's are; a real log's slowly wandering receiver error shows as 0.6-0.98).
  double lag1() const { return z2_sum > 0.0 ? lag_sum / z2_sum : 0.0; }
};

struct InnovationStats {
  std::array<ComponentStats, kSources> source{};
  std::array<std::array<ComponentStats, kPhaseCount>, kSources> by_phase{};
  double total_nll() const;
};

/// The flight phase from the solution: yaw rate, vertical speed, acceleration
/// and speed over the last 0.1 s (as nav.csv's rows).
class PhaseTracker {
 public:
  /// The phase after this solution.
  Phase on_nav(const est::NavOutput& out);
  Phase phase() const { return phase_; }

 private:
  Phase phase_ = Phase::Straight;
  bool have_prev_ = false;
  double prev_t_s_ = 0.0, prev_yaw_deg_ = 0.0, prev_speed_m_s_ = 0.0;
};

/// Scores a replay's innovations while it runs: each innovation component
/// against its predicted sigma, in the flight phase of the latest solution.
class InnovationStatsListener final : public replay::ReplayListener {
 public:
  void on_nav(const est::NavOutput& out) override { phases_.on_nav(out); }
  void on_innovation(const est::InnovationRecord& rec) override;
  const InnovationStats& stats() const { return stats_; }

 private:
  InnovationStats stats_;
  PhaseTracker phases_;
  std::array<std::array<double, 3>, kSources> prev_z_{};  // per source and component, for lag_sum
  std::array<std::array<bool, 3>, kSources> have_prev_{};
};

}  // namespace sinu::diagnose
