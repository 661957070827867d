#include "estimator/ekf/aiding/field_model/field_model.hpp"

#include <algorithm>
#include <cmath>

namespace sinu::est {

Measurement field_model_measurement(const ErrorStateFilter& filter, const Eigen::Vector3d& model_field_n_uT,
                                    double strength_sigma_uT, double inclination_sigma_rad, double gate_sigma) {
  const StateLayout& L = filter.layout();
  const Eigen::Vector3d F = filter.mag_earth_field_n_uT();
  const Eigen::Index field = L.of(Effect::MagEarthField).start;
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.innovation = MeasVec::Zero(2);
  m.H = MeasJacobian::Zero(2, L.dim);
  // Row 0: the strength; row 1: the inclination I = atan2(F_d, H), H = |F_ne|.
  // (|F_n| / H <= 1 keeps the gradient finite; the floor only avoids 0 / 0 for a vertical field.)
  const double h = std::max(std::hypot(F.x(), F.y()), 1e-9), f2 = F.squaredNorm();
  const Eigen::Vector3d g_strength = F / F.norm();
  const Eigen::Vector3d g_incl(-F.z() * F.x() / (h * f2), -F.z() * F.y() / (h * f2), h / f2);
  m.innovation(0) = F.norm() - model_field_n_uT.norm();
  m.innovation(1) = std::atan2(F.z(), h) - std::atan2(model_field_n_uT.z(), model_field_n_uT.head<2>().norm());
  m.H.block(0, field, 1, 3) = -g_strength.transpose();
  m.H.block(1, field, 1, 3) = -g_incl.transpose();
  m.H.block(1, L.att.start, 1, 3) = g_incl.cross(F).transpose();
  m.R = MeasMat::Zero(2, 2);
  m.R(0, 0) = strength_sigma_uT * strength_sigma_uT;
  m.R(1, 1) = inclination_sigma_rad * inclination_sigma_rad;
  return m;
}

Measurement soft_iron_scale_measurement(const ErrorStateFilter& filter, double sigma, double gate_sigma) {
  const StateLayout& L = filter.layout();
  const Slice& D = L.of(Effect::MagSoftIron);
  const EffectView v = filter.view(Effect::MagSoftIron);
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.innovation = MeasVec::Constant(1, v.v[0] + v.v[1] + v.v[2]);
  m.H = MeasJacobian::Zero(1, L.dim);
  m.H.block(0, D.start, 1, 3).setConstant(-1.0);
  m.R = MeasMat::Constant(1, 1, sigma * sigma);
  return m;
}

}  // namespace sinu::est
