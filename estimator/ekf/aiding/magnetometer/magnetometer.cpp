#include "estimator/ekf/aiding/magnetometer/magnetometer.hpp"

#include "estimator/ins/rotation.hpp"

namespace sinu::est {

Measurement magnetometer_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                     const Eigen::Vector3d& mag_b_uT, double sigma_uT, double gate_sigma) {
  const StateLayout& L = filter.layout();
  const Eigen::Matrix3d C_bn = nav.C_nb().transpose();
  const Eigen::Vector3d F_n = filter.mag_earth_field_n_uT();
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.innovation = C_bn * F_n + filter.mag_hard_iron_b_uT() - mag_b_uT;
  m.H = MeasJacobian::Zero(3, L.dim);
  m.H.block(0, L.att.start, 3, 3) = -C_bn * skew(F_n);
  m.H.block(0, L.of(Effect::MagEarthField).start, 3, 3) = -C_bn;
  if (L.has(Effect::MagHardIron)) m.H.block(0, L.of(Effect::MagHardIron).start, 3, 3) = -Eigen::Matrix3d::Identity();
  m.R = Eigen::Matrix3d::Identity() * (sigma_uT * sigma_uT);
  return m;
}

}  // namespace sinu::est
