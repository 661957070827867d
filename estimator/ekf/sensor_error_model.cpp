#include "estimator/ekf/sensor_error_model.hpp"

namespace sinu::est {

AxisBlock ar_companion(const ArAxis& axis, Eigen::Index order) {
  AxisBlock F = AxisBlock::Zero(order, order);
  for (Eigen::Index j = 0; j < order && j < axis.order; ++j) F(0, j) = -axis.a[static_cast<std::size_t>(j + 1)];
  for (Eigen::Index i = 1; i < order; ++i) F(i, i - 1) = 1.0;
  return F;
}

AxisBlock stationary_covariance(const SensorNoise& noise, Eigen::Index axis, Eigen::Index order) {
  const auto k = static_cast<std::size_t>(axis);
  if (noise.kind == NoiseModelKind::GaussMarkov) return AxisBlock::Constant(1, 1, noise.gm[k].variance);
  // X = sum_i F^i Q F^iT by doubling: X <- X + A X A^T, A <- A^2. 2^30 steps
  // cover any stable model a calibration produces (poles below 1 - 1e-9).
  AxisBlock A = ar_companion(noise.ar[k], order);
  AxisBlock X = AxisBlock::Zero(order, order);
  X(0, 0) = noise.ar[k].variance;
  for (int i = 0; i < 30; ++i) {
    X = (X + A * X * A.transpose()).eval();
    A = (A * A).eval();
  }
  return 0.5 * (X + X.transpose());
}

}  // namespace sinu::est
