#include "estimator/ekf/aiding/magnetometer/magnetometer.hpp"

#include "estimator/ins/rotation.hpp"

namespace sinu::est {

Measurement magnetometer_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                     const Eigen::Vector3d& mag_b_uT, double sigma_uT, double gate_sigma) {
  const StateLayout& L = filter.layout();
  const Eigen::Matrix3d C_bn = nav.C_nb().transpose();
  const Eigen::Vector3d F_n = filter.mag_earth_field_n_uT();
  const Eigen::Matrix3d S = filter.mag_soft_iron();
  const Eigen::Vector3d u = C_bn * F_n;  // the Earth field in the body frame
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.innovation = S * u + filter.mag_hard_iron_b_uT() - mag_b_uT;
  m.H = MeasJacobian::Zero(3, L.dim);
  // y = -S C_bn [F x] phi - S C_bn dF - dh = -S C_bn e - dh: with the invariant
  // field error e (state_layout.hpp) the attitude drops out.
  m.H.block(0, L.of(Effect::MagEarthField).start, 3, 3) = -S * C_bn;
  if (L.has(Effect::MagSoftIron)) {  // d(S u)/dD for D = [xx yy zz xy xz yz]
    Eigen::Matrix<double, 3, 6> J;
    J << u.x(), 0.0, 0.0, u.y(), u.z(), 0.0,  //
        0.0, u.y(), 0.0, u.x(), 0.0, u.z(),   //
        0.0, 0.0, u.z(), 0.0, u.x(), u.y();
    m.H.block(0, L.of(Effect::MagSoftIron).start, 3, 6) = -J;
  }
  if (L.has(Effect::MagHardIron)) m.H.block(0, L.of(Effect::MagHardIron).start, 3, 3) = -Eigen::Matrix3d::Identity();
  m.R = Eigen::Matrix3d::Identity() * (sigma_uT * sigma_uT);
  return m;
}

}  // namespace sinu::est
