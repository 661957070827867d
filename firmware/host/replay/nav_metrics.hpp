#pragma once
// Accumulates the comparison of the navigation solution with truth.csv (at
// truth instants, the solution interpolated between IMU instants), NEES,
// NIS per aiding source and the per-outage horizontal drift. Fixed storage.
#include <array>
#include <cstdint>
#include <vector>

#include "estimator/nav/navigator.hpp"
#include "estimator/util/ring_buffer.hpp"
#include "firmware/host/replay/replay_options.hpp"

namespace sinu::replay {

struct TruthPoint {
  double t_s = 0.0;
  double lat_rad = 0.0, lon_rad = 0.0, h_m = 0.0;
  Eigen::Vector3d v_n = Eigen::Vector3d::Zero();
  bool has_vel = false, has_att = false;
  Eigen::Quaterniond q_nb = Eigen::Quaterniond::Identity();
};

struct ChiStats {
  std::uint64_t count = 0, inside = 0;
  double sum = 0.0;
  void add(double v, double lo, double hi);
  double mean() const { return count ? sum / static_cast<double>(count) : 0.0; }
  double inside_fraction() const { return count ? static_cast<double>(inside) / static_cast<double>(count) : 0.0; }
};

struct OutageDrift {
  Outage window;
  double max_drift_h_m = 0.0;
  std::uint64_t points = 0;
  std::uint64_t fixes_withheld = 0;  // GNSS epochs inside it (none: the window missed the data's clock)
};

/// sum |dp + v delta|^2 over the fixes (dp: fix minus truth, v: the truth's
/// velocity), for any delta chosen afterwards: the fixes re-timed by the
/// latency the filter learnt against the configured one.
struct RetimedSquares {
  double dp2 = 0.0, dp_v = 0.0, v2 = 0.0;
  template <class Dp, class V> void add(const Dp& dp, const V& v) {
    dp2 += dp.squaredNorm();
    dp_v += dp.dot(v);
    v2 += v.squaredNorm();
  }
  double at(double delta_s) const { return dp2 + 2.0 * delta_s * dp_v + delta_s * delta_s * v2; }
};

/// A GNSS fix as the receiver gave it: the antenna at its time of validity.
struct GnssPoint {
  double t_s = 0.0;
  double lat_rad = 0.0, lon_rad = 0.0, h_m = 0.0;
};

class NavMetrics {
 public:
  /// Outages are copied once (init-time allocation).
  void init(const std::vector<Outage>& outages, const Eigen::Vector3d& lever_arm_b_m);
  /// One truth instant and the solution (interpolated) at that instant.
  void add_truth(const TruthPoint& truth, const est::NavState& nav, const Eigen::Matrix<double, 9, 9>& P_nav);
  void add_innovation(const est::InnovationRecord& rec);
  /// A fix the navigator was given, scored against truth (interpolated to its
  /// time, moved to the antenna by the lever arm) as the raw-GNSS baseline.
  void add_gnss(const GnssPoint& fix);

  std::uint64_t compared = 0, compared_att = 0, compared_vel = 0;
  double sum_h2 = 0.0, sum_v2 = 0.0, sum_vel2 = 0.0, sum_att2 = 0.0;
  std::uint64_t gnss_compared = 0;
  RetimedSquares gnss_h, gnss_v;  // horizontal, vertical
  ChiStats nees;
  // The same from kSettleS after the first solution on: the priors of a
  // fresh alignment (heading without the declination, tilt against the
  // accelerometer bias) are honest but wide, and the NEES sits below its
  // lower bound while they last.
  static constexpr double kSettleS = 60.0;
  ChiStats nees_settled;
  int nees_dof = 0;
  std::array<ChiStats, est::kAidingSourceCount> nis{};
  std::vector<OutageDrift> outages;

 private:
  void score_gnss(const TruthPoint& before, const TruthPoint& after);
  est::RingBuffer<GnssPoint, 64> pending_gnss_;
  TruthPoint prev_truth_;
  bool have_prev_truth_ = false;
  double first_truth_t_s_ = 0.0;
  Eigen::Vector3d lever_arm_b_m_ = Eigen::Vector3d::Zero();
};

/// Two-sided 95% chi-square bounds for 1..9 degrees of freedom.
void chi2_bounds_95(int dof, double& lo, double& hi);

}  // namespace sinu::replay
