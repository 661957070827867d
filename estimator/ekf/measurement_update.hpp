#pragma once
// One vector measurement (up to three components) fused into the error
// state: innovation y = h(x_hat) - z, so that y ~ H dx + noise with the
// conventions of state_layout.hpp. Joseph-form covariance update
//   P <- (I - K H) P (I - K H)^T + K R K^T
// with the upper triangle computed and mirrored. Innovation test ratio per
// component, PX4 style: y_i^2 / (gate^2 S_ii); any ratio > 1 (or a non-finite
// one) rejects the whole measurement.
#include "estimator/ekf/state_layout.hpp"

namespace sinu::est {

inline constexpr Eigen::Index kMaxMeasurementRows = 3;
using MeasVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxMeasurementRows, 1>;
using MeasMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxMeasurementRows, kMaxMeasurementRows>;
using MeasJacobian = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxMeasurementRows, kMaxStates>;

struct Measurement {
  MeasVec innovation;    // h(x_hat) - z
  MeasJacobian H;        // rows x dim
  MeasMat R;             // measurement noise covariance
  double gate_sigma = 5.0;
};

struct UpdateResult {
  Eigen::Index rows = 0;
  Eigen::Vector3d innovation = Eigen::Vector3d::Zero();
  Eigen::Vector3d innovation_sigma = Eigen::Vector3d::Zero();  // sqrt(S_ii)
  Eigen::Vector3d noise_sigma = Eigen::Vector3d::Zero();       // sqrt(R_ii): the measurement noise used
  Eigen::Vector3d test_ratio = Eigen::Vector3d::Zero();
  double nis = 0.0;  // y^T S^-1 y
  bool accepted = false;
};

/// Computes the test; when it passes, updates P and sets dx = K y (the
/// error-state estimate, to be fed back by the caller). dx is zero otherwise.
/// States in `frozen` get a zero gain (they learn nothing from this update,
/// PX4's inhibited states); the Joseph form keeps P right for that gain.
UpdateResult fuse_measurement(StateMat& P, StateVec& dx, const Measurement& m, const StateMask& frozen = {});

}  // namespace sinu::est
