#pragma once
// Transition of one sensor axis's error block over an interval: GM1
// (scalar exp(-dt/tau)) or AR(p) in companion form, stepped once per AR
// sample period (the AR models are discrete at the calibration's rate).
#include "estimator/ekf/sensor_noise.hpp"

namespace sinu::est {

using AxisBlock = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxArOrder, kMaxArOrder>;

/// Companion matrix of x_k = -a1 x_{k-1} - ... - ap x_{k-p} + w_k, padded
/// to `order` (extra lags carry zero coefficients).
AxisBlock ar_companion(const ArAxis& axis, Eigen::Index order);

/// Stationary covariance of the companion-form process (discrete Lyapunov
/// solved by doubling); the GM case is sigma^2.
AxisBlock stationary_covariance(const SensorNoise& noise, Eigen::Index axis, Eigen::Index order);

}  // namespace sinu::est
