#include "estimator/ekf/aiding/nonholonomic/nonholonomic.hpp"

#include <cmath>

#include "estimator/ins/rotation.hpp"

namespace sinu::est {

Measurement nonholonomic_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                     const Eigen::Vector3d& w_b, const NonholonomicConfig& cfg, double gate_sigma,
                                     const VehicleAxes& axes) {
  const StateLayout& L = filter.layout();
  const Eigen::Matrix3d C_bn = nav.C_nb().transpose();
  const Eigen::Vector3d v_b = C_bn * nav.v_n_m_s;
  const Eigen::Matrix3d H_att = -C_bn * skew(nav.v_n_m_s);
  const Eigen::Vector3d* rows[2] = {&axes.lateral_b, &axes.vertical_b};
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.innovation = Eigen::Vector2d(axes.lateral_b.dot(v_b), axes.vertical_b.dot(v_b));
  m.H = MeasJacobian::Zero(2, L.dim);
  for (Eigen::Index r = 0; r < 2; ++r) {
    const Eigen::Vector3d& a = *rows[r];
    m.H.block(r, L.vel.start, 1, 3) = a.transpose() * C_bn;
    m.H.block(r, L.att.start, 1, 3) = a.transpose() * H_att;
  }
  const double turn = cfg.sigma_per_yaw_rate_m * std::abs(w_b.dot(axes.vertical_b));
  const double lat = std::hypot(cfg.lateral_sigma_m_s, turn), vert = cfg.vertical_sigma_m_s;
  m.R = MeasMat::Zero(2, 2);
  m.R(0, 0) = lat * lat;
  m.R(1, 1) = vert * vert;
  return m;
}

}  // namespace sinu::est
