#include "estimator/ekf/aiding/declination/declination.hpp"

#include <cmath>
#include <numbers>

namespace sinu::est {

Measurement declination_measurement(const ErrorStateFilter& filter, double declination_rad, double sigma_rad,
                                    double gate_sigma) {
  const StateLayout& L = filter.layout();
  const Eigen::Vector3d F = filter.mag_earth_field_n_uT();
  const double h2 = F.x() * F.x() + F.y() * F.y();
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.innovation = MeasVec::Zero(1);
  m.innovation(0) = std::remainder(std::atan2(F.y(), F.x()) - declination_rad, 2.0 * std::numbers::pi);
  m.H = MeasJacobian::Zero(1, L.dim);
  const Eigen::Vector3d a = Eigen::Vector3d(-F.y(), F.x(), 0.0) / h2;
  m.H.block(0, L.of(Effect::MagEarthField).start, 1, 3) = -a.transpose();
  m.H.block(0, L.att.start, 1, 3) = a.cross(F).transpose();
  m.R = MeasMat::Identity(1, 1) * (sigma_rad * sigma_rad);
  return m;
}

}  // namespace sinu::est
