#include "firmware/host/sim/bench_schedule.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "firmware/host/calibration/bench_positions.hpp"

namespace sinu::sim {

namespace {

// Body -> NED with the body axis `up_b` pointing up, turned by `heading_rad`
// about the vertical and tilted by the placement error (small angles about north and east).
Eigen::Matrix3d attitude(const Eigen::Vector3d& up_b, double heading_rad, double tilt_n_rad, double tilt_e_rad) {
  const Eigen::Vector3d up_n(0.0, 0.0, -1.0);
  Eigen::Matrix3d C = Eigen::Quaterniond::FromTwoVectors(up_b, up_n).toRotationMatrix();
  C = Eigen::AngleAxisd(heading_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix() * C;
  return (Eigen::AngleAxisd(tilt_n_rad, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(tilt_e_rad, Eigen::Vector3d::UnitY())).toRotationMatrix() * C;
}

}  // namespace

BenchSchedule::BenchSchedule(std::size_t positions, double hold_s, double transition_s, double first_heading_rad,
                             Rng& rng)
    : hold_s_(hold_s), transition_s_(transition_s) {
  positions_.resize(positions);
  for (std::size_t k = 0; k < positions; ++k) {
    BenchPosition& p = positions_[k];
    p.index = k;
    const double heading = k == 0 ? first_heading_rad : rng.uniform(0.0, 2.0 * std::numbers::pi);
    const double tn = kPlacementSigma_rad * rng.normal(), te = kPlacementSigma_rad * rng.normal();
    p.C_nb = attitude(calibration::position_up_b(k), heading, tn, te);
    p.still_from_s = static_cast<double>(k) * (hold_s + transition_s);
    p.still_to_s = p.still_from_s + hold_s;
  }
}

double BenchSchedule::duration_s() const {
  const auto n = static_cast<double>(positions_.size());
  return n * hold_s_ + (n - 1.0) * transition_s_;
}

void BenchSchedule::at(double tau, Eigen::Matrix3d& C_nb, Eigen::Vector3d& omega_nb_b) const {
  const double cycle = hold_s_ + transition_s_;
  const auto k = std::min(static_cast<std::size_t>(std::max(0.0, tau) / cycle), positions_.size() - 1);
  const double in = tau - static_cast<double>(k) * cycle;
  omega_nb_b.setZero();
  C_nb = positions_[k].C_nb;
  if (in <= hold_s_ || k + 1 == positions_.size()) return;
  // Turning to the next attitude: C(s) = R(theta s, axis) C_k, s = (1 - cos(pi x)) / 2 over the transition.
  const Eigen::AngleAxisd rel(positions_[k + 1].C_nb * C_nb.transpose());
  const double x = std::min(1.0, (in - hold_s_) / transition_s_);
  const double s = 0.5 * (1.0 - std::cos(std::numbers::pi * x));
  const double s_dot = 0.5 * std::numbers::pi / transition_s_ * std::sin(std::numbers::pi * x);
  C_nb = Eigen::AngleAxisd(rel.angle() * s, rel.axis()).toRotationMatrix() * C_nb;
  omega_nb_b = C_nb.transpose() * (rel.axis() * rel.angle() * s_dot);
}

}  // namespace sinu::sim
