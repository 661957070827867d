#pragma once
// Strapdown mechanisation in NED on WGS-84 (Groves ch. 5.4 / Savage's
// two-speed structure collapsed to one speed).
//
// Inputs are instantaneous samples (rate and specific force at instants
// t_{k-1} and t_k), not increments. Over each interval both are taken as
// linear in time, which gives exactly
//   attitude increment   dtheta = (w0 + w1) T/2 + (w0 x w1) T^2/12   (coning)
//   velocity increment   dv     = (f0 + f1) T/2 + int alpha(t) x f(t) dt  (rotation + sculling)
// The navigation-frame rotation (Earth rate + transport rate), gravity
// (normal gravity with height) and Coriolis use mid-interval values
// extrapolated from the previous step. Position is integrated with the
// trapezoidal mean of old and new velocity. Works at any rate 20-1000 Hz.
#include "estimator/ins/imu_sample.hpp"
#include "estimator/ins/nav_state.hpp"

namespace sinu::est {

/// Compensated body-frame inputs at one instant.
struct BodyRates {
  Eigen::Vector3d specific_force_b_m_s2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_rate_b_rad_s = Eigen::Vector3d::Zero();
};

/// Advances `nav` from prev.t to t over one interval of length dt_s, with the
/// inputs sampled at the interval's start (`prev`) and end (`cur`).
/// Also returns the mean NED specific force over the interval (for the EKF).
void strapdown_step(NavState& nav, const BodyRates& prev, const BodyRates& cur, double dt_s,
                    Eigen::Vector3d& mean_specific_force_n_m_s2);

}  // namespace sinu::est
