#include "estimator/ekf/aiding/nonholonomic/nonholonomic.hpp"

#include <cmath>

#include "estimator/ekf/effects/effect_list.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

namespace {

/// What an effect's nonholonomic() hook sees and writes (effects/*.hpp): the
/// axes in use, and its columns.
struct NonholonomicTerms {
  VehicleAxes axes;
  const Eigen::Vector3d& v_b;
  MeasJacobian& H;
  Slice slice;
};

}  // namespace

VehicleAxes vehicle_axes_in_use(const ErrorStateFilter& filter, const VehicleAxes& found) {
  VehicleAxes axes = found;
  for_each_effect([&]<class E>() {
    if constexpr (requires { E::turn_vehicle_axes(filter.view(E::spec.effect), axes); }) {
      E::turn_vehicle_axes(filter.view(E::spec.effect), axes);
    }
  });
  return axes;
}

Measurement nonholonomic_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                     const Eigen::Vector3d& w_b, const NonholonomicConfig& cfg, double gate_sigma,
                                     const VehicleAxes& found) {
  const StateLayout& L = filter.layout();
  const Eigen::Matrix3d C_bn = nav.C_nb().transpose();
  const Eigen::Vector3d v_b = C_bn * nav.v_n_m_s;
  const Eigen::Matrix3d H_att = -C_bn * skew(nav.v_n_m_s);
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.H = MeasJacobian::Zero(2, L.dim);
  NonholonomicTerms t{vehicle_axes_in_use(filter, found), v_b, m.H, {}};
  for_each_effect([&]<class E>() {
    if constexpr (requires { E::nonholonomic(filter.view(E::spec.effect), t); }) {
      t.slice = L.of(E::spec.effect);
      E::nonholonomic(filter.view(E::spec.effect), t);
    }
  });
  const Eigen::Vector3d* rows[2] = {&t.axes.lateral_b, &t.axes.vertical_b};
  m.innovation = Eigen::Vector2d(t.axes.lateral_b.dot(v_b), t.axes.vertical_b.dot(v_b));
  for (Eigen::Index r = 0; r < 2; ++r) {
    const Eigen::Vector3d& a = *rows[r];
    m.H.block(r, L.vel.start, 1, 3) = a.transpose() * C_bn;
    m.H.block(r, L.att.start, 1, 3) = a.transpose() * H_att;
  }
  const double turn = cfg.sigma_per_yaw_rate_m * std::abs(w_b.dot(t.axes.vertical_b));
  const double lat = std::hypot(cfg.lateral_sigma_m_s, turn), vert = cfg.vertical_sigma_m_s;
  m.R = MeasMat::Zero(2, 2);
  m.R(0, 0) = lat * lat;
  m.R(1, 1) = vert * vert;
  return m;
}

}  // namespace sinu::est
