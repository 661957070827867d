#include "estimator/ekf/sensor_noise.hpp"

#include <cmath>

namespace sinu::est {

Eigen::Index SensorNoise::order() const {
  if (kind == NoiseModelKind::GaussMarkov) return 1;
  Eigen::Index p = 1;
  for (const ArAxis& axis : ar) p = axis.order > p ? axis.order : p;
  return p;
}

void SensorNoise::scale_coloured(double factor) {
  for (GaussMarkovAxis& g : gm) g.variance *= factor;
  for (ArAxis& a : ar) a.variance *= factor;
  accel_bias_walk *= std::sqrt(factor);
  gyro_bias_walk *= std::sqrt(factor);
}

SensorNoise SensorNoise::defaults(NoiseModelKind kind) {
  constexpr double kAccelSigma = 0.05, kGyroSigma = 5e-3, kTau = 300.0, kPeriod = 0.025;
  SensorNoise n;
  n.kind = kind;
  n.ar_sample_period_s = kPeriod;
  n.accel_white_m_s2_rthz = 2.3e-3;
  n.gyro_white_rad_s_rthz = 2.6e-4;
  for (Eigen::Index i = 0; i < kSensorAxes; ++i) {
    const double sigma = i < sensor_axis::kFirstGyro ? kAccelSigma : kGyroSigma;
    const auto k = static_cast<std::size_t>(i);
    n.gm[k] = {kTau, sigma * sigma};
    const double phi = std::exp(-kPeriod / kTau);
    n.ar[k].order = 1;
    n.ar[k].a = {1.0, -phi, 0.0, 0.0, 0.0};
    n.ar[k].variance = sigma * sigma * (1.0 - phi * phi);
  }
  return n;
}

}  // namespace sinu::est
