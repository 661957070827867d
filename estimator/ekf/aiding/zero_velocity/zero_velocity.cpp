#include "estimator/ekf/aiding/zero_velocity/zero_velocity.hpp"

namespace sinu::est {

Measurement zero_velocity_measurement(const ErrorStateFilter& filter, const NavState& nav, double sigma_m_s,
                                      double gate_sigma) {
  const StateLayout& L = filter.layout();
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.innovation = nav.v_n_m_s;
  m.H = MeasJacobian::Zero(3, L.dim);
  m.H.block(0, L.vel.start, 3, 3).setIdentity();
  m.R = MeasMat::Identity(3, 3) * (sigma_m_s * sigma_m_s);
  return m;
}

}  // namespace sinu::est
