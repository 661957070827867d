#pragma once
// A multi-position bench session (`sinu simulate static --positions N`): the
// unit is held still in N attitudes (calibration/bench_positions.hpp: the six
// faces, then tilted ones), each for `hold_s`, and turned from one to the next
// in `transition_s` about a fixed axis with a cosine profile (rate zero at both
// ends), its centre at the IMU (no linear acceleration). Each attitude is what
// a person placing the board makes of it: the asked-for axis up, within a
// placement error of about a degree, at any heading (the first: the site's).
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "firmware/host/sim/rng.hpp"

namespace sinu::sim {

struct BenchPosition {
  std::size_t index = 0;            // into calibration::kPositionUp
  Eigen::Matrix3d C_nb = Eigen::Matrix3d::Identity();  // body -> NED while held
  double still_from_s = 0.0, still_to_s = 0.0;         // since the session's start
};

class BenchSchedule {
 public:
  static constexpr double kPlacementSigma_rad = 0.0175;  // 1 deg per horizontal axis

  /// `positions` >= 2; the first attitude's heading is `first_heading_rad`.
  BenchSchedule(std::size_t positions, double hold_s, double transition_s, double first_heading_rad, Rng& rng);
  /// The attitude and the body's rate with respect to NED `tau_s` after the start.
  void at(double tau_s, Eigen::Matrix3d& C_nb, Eigen::Vector3d& omega_nb_b_rad_s) const;
  const std::vector<BenchPosition>& positions() const { return positions_; }
  double duration_s() const;

 private:
  std::vector<BenchPosition> positions_;
  double hold_s_, transition_s_;
};

}  // namespace sinu::sim
