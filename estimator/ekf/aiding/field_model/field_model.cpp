#include "estimator/ekf/aiding/field_model/field_model.hpp"

namespace sinu::est {

Measurement field_model_measurement(const ErrorStateFilter& filter, const Eigen::Vector3d& model_field_n_uT,
                                    double sigma_uT, double gate_sigma) {
  const StateLayout& L = filter.layout();
  const Eigen::Vector3d F = filter.mag_earth_field_n_uT();
  const Eigen::Index field = L.of(Effect::MagEarthField).start;
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.innovation = MeasVec::Zero(2);
  m.H = MeasJacobian::Zero(2, L.dim);
  // Row 0: the strength; row 1: the down component.
  const Eigen::Vector3d g_strength = F / F.norm(), g_down = Eigen::Vector3d::UnitZ();
  m.innovation(0) = F.norm() - model_field_n_uT.norm();
  m.innovation(1) = F.z() - model_field_n_uT.z();
  m.H.block(0, field, 1, 3) = -g_strength.transpose();
  m.H.block(1, field, 1, 3) = -g_down.transpose();
  m.H.block(1, L.att.start, 1, 3) = g_down.cross(F).transpose();
  m.R = MeasMat::Identity(2, 2) * (sigma_uT * sigma_uT);
  return m;
}

}  // namespace sinu::est
