#include "estimator/ekf/aiding/nonholonomic/nonholonomic.hpp"

#include <cmath>

#include "estimator/ins/rotation.hpp"

namespace sinu::est {

Measurement nonholonomic_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                     const Eigen::Vector3d& w_b, const NonholonomicConfig& cfg, double gate_sigma) {
  const StateLayout& L = filter.layout();
  const Eigen::Matrix3d C_bn = nav.C_nb().transpose();
  const Eigen::Vector3d v_b = C_bn * nav.v_n_m_s;
  const Eigen::Matrix3d H_att = -C_bn * skew(nav.v_n_m_s);
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.innovation = v_b.tail<2>();
  m.H = MeasJacobian::Zero(2, L.dim);
  m.H.block(0, L.vel.start, 2, 3) = C_bn.bottomRows<2>();
  m.H.block(0, L.att.start, 2, 3) = H_att.bottomRows<2>();
  const double turn = cfg.sigma_per_yaw_rate_m * std::abs(w_b.z());
  const double lat = std::hypot(cfg.lateral_sigma_m_s, turn), vert = cfg.vertical_sigma_m_s;
  m.R = MeasMat::Zero(2, 2);
  m.R(0, 0) = lat * lat;
  m.R(1, 1) = vert * vert;
  return m;
}

}  // namespace sinu::est
