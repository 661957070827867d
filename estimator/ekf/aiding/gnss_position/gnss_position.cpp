#include "estimator/ekf/aiding/gnss_position/gnss_position.hpp"

#include <cmath>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

Measurement gnss_position_measurement(const ErrorStateFilter& filter, const NavState& nav, double dt_back,
                                      const GnssObservation& z, double gate_sigma) {
  const StateLayout& L = filter.layout();
  const double rm = wgs84::meridian_radius_m(nav.lat_rad) + nav.h_m;
  const double rn = wgs84::transverse_radius_m(nav.lat_rad) + nav.h_m;
  const Eigen::Matrix3d C = nav.C_nb();
  const Eigen::Vector3d lever_n = C * filter.lever_arm_b_m();
  // Predicted antenna minus measured antenna, NED metres.
  const Eigen::Vector3d offset_n = lever_n - nav.v_n_m_s * dt_back;
  Eigen::Vector3d y;
  y.x() = (nav.lat_rad - z.lat_rad) * rm + offset_n.x();
  y.y() = (nav.lon_rad - z.lon_rad) * rn * std::cos(nav.lat_rad) + offset_n.y();
  y.z() = -(nav.h_m - z.h_m) + offset_n.z();
  const bool bias = L.has(Effect::GpsPositionBias);
  if (bias) y += filter.gps_position_bias_ned_m();  // z_hat = antenna + b_hat

  Measurement m;
  m.gate_sigma = gate_sigma;
  m.innovation = y;
  m.H = MeasJacobian::Zero(3, L.dim);
  m.H.block(0, L.pos.start, 3, 3).setIdentity();
  m.H.block(0, L.att.start, 3, 3) = skew(lever_n);
  if (L.has(Effect::LeverArm)) m.H.block(0, L.of(Effect::LeverArm).start, 3, 3) = -C;
  if (L.has(Effect::GpsLatency)) m.H.block(0, L.of(Effect::GpsLatency).start, 3, 1) = nav.v_n_m_s;
  if (bias) m.H.block(0, L.of(Effect::GpsPositionBias).start, 3, 3) = -Eigen::Matrix3d::Identity();
  // With the bias states the fix's variance is split: its correlated part
  // lives in the bias states, the rest is white.
  Eigen::Vector3d var = z.sigma_ned_m.cwiseAbs2();
  if (bias) var *= 1.0 - filter.tuning().gps_bias_variance_fraction;
  m.R = var.asDiagonal();
  return m;
}

}  // namespace sinu::est
