#include "estimator/ekf/aiding/gnss_velocity/gnss_velocity.hpp"

#include "estimator/ins/rotation.hpp"

namespace sinu::est {

Measurement gnss_velocity_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                      const Eigen::Vector3d& w_b, const Eigen::Vector3d& accel_n,
                                      double dt_back, const GnssObservation& z, double gate_sigma) {
  const StateLayout& L = filter.layout();
  const Eigen::Matrix3d C = nav.C_nb();
  const Eigen::Vector3d lever_vel_n = C * w_b.cross(filter.lever_arm_b_m());
  const Eigen::Vector3d predicted = nav.v_n_m_s + lever_vel_n - accel_n * dt_back;

  Measurement m;
  m.gate_sigma = gate_sigma;
  m.innovation = predicted.head<2>() - z.v_ne_m_s;
  m.H = MeasJacobian::Zero(2, L.dim);
  m.H.block(0, L.vel.start, 2, 3) = Eigen::Matrix<double, 2, 3>::Identity();
  m.H.block(0, L.att.start, 2, 3) = skew(lever_vel_n).topRows<2>();
  if (L.has(Effect::LeverArm)) m.H.block(0, L.of(Effect::LeverArm).start, 2, 3) = -(C * skew(w_b)).topRows<2>();
  if (L.has(Effect::GpsLatency)) m.H.block(0, L.of(Effect::GpsLatency).start, 2, 1) = accel_n.head<2>();
  m.R = MeasMat::Identity(2, 2) * (z.sigma_vel_m_s * z.sigma_vel_m_s);
  return m;
}

}  // namespace sinu::est
