#include "estimator/ekf/aiding/gnss_position/gnss_position.hpp"

#include <cmath>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ekf/effects/effect_list.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

namespace {

/// What an effect's gnss_position() hook sees and writes (effects/*.hpp).
struct GnssPositionTerms {
  const NavState& nav;
  const Eigen::Matrix3d& C;  // C_nb
  const EffectTuning& tuning;
  MeasJacobian& H;
  Eigen::Index att;                      // attitude columns
  Eigen::Vector3d antenna_offset_n;      // antenna minus IMU, NED (from zero)
  Eigen::Vector3d measurement_offset_n;  // fix minus antenna, NED (from zero)
  Eigen::Vector3d white_variance;        // the fix's variance not carried by states
  Eigen::Vector3d white_fraction;        // of the stated variance, when states carry the rest
  Slice slice;                           // the effect's states (inactive: size 0)
};

}  // namespace

Measurement gnss_position_measurement(const ErrorStateFilter& filter, const NavState& nav, double dt_back,
                                      const GnssObservation& z, double gate_sigma) {
  const StateLayout& L = filter.layout();
  const double rm = wgs84::meridian_radius_m(nav.lat_rad) + nav.h_m;
  const double rn = wgs84::transverse_radius_m(nav.lat_rad) + nav.h_m;
  const Eigen::Matrix3d C = nav.C_nb();
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.H = MeasJacobian::Zero(3, L.dim);
  m.H.block(0, L.pos.start, 3, 3).setIdentity();
  GnssPositionTerms t{nav, C, filter.tuning(), m.H, L.att.start, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                      z.sigma_ned_m.cwiseAbs2(), filter.gps_white_fraction_ned(), {}};
  for_each_effect([&]<class E>() {
    if constexpr (requires { E::gnss_position(filter.view(E::spec.effect), t); }) {
      t.slice = L.of(E::spec.effect);
      E::gnss_position(filter.view(E::spec.effect), t);
    }
  });
  // Predicted antenna minus measured antenna, NED metres, taken back to the fix's time.
  const Eigen::Vector3d offset_n = t.antenna_offset_n - nav.v_n_m_s * dt_back;
  Eigen::Vector3d y;
  y.x() = (nav.lat_rad - z.lat_rad) * rm + offset_n.x();
  y.y() = wgs84::lon_difference_rad(nav.lon_rad, z.lon_rad) * rn * std::cos(nav.lat_rad) + offset_n.y();
  y.z() = -(nav.h_m - z.h_m) + offset_n.z();
  y += t.measurement_offset_n;
  const Eigen::Index rows = z.has_height ? 3 : 2;
  m.innovation = y.head(rows);
  m.R = t.white_variance.head(rows).asDiagonal();
  if (rows < 3) m.H.conservativeResize(rows, Eigen::NoChange);
  return m;
}

}  // namespace sinu::est
