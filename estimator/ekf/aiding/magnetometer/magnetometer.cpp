#include "estimator/ekf/aiding/magnetometer/magnetometer.hpp"

#include "estimator/ekf/effects/effect_list.hpp"

namespace sinu::est {

namespace {

/// What an effect's magnetometer() hook sees and writes (effects/*.hpp).
struct MagnetometerTerms {
  const Eigen::Matrix3d& C_bn;
  const Eigen::Matrix3d& S;  // soft iron I + D
  const Eigen::Vector3d& u;  // the Earth field in the body frame, C_bn F
  MeasJacobian& H;
  Slice slice;
};

}  // namespace

Measurement magnetometer_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                     const Eigen::Vector3d& mag_b_uT, double sigma_uT, double gate_sigma) {
  const StateLayout& L = filter.layout();
  const Eigen::Matrix3d C_bn = nav.C_nb().transpose();
  const Eigen::Matrix3d S = filter.mag_soft_iron();
  const Eigen::Vector3d u = C_bn * filter.mag_earth_field_n_uT();
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.innovation = S * u + filter.mag_hard_iron_b_uT() - mag_b_uT;
  m.H = MeasJacobian::Zero(3, L.dim);
  MagnetometerTerms t{C_bn, S, u, m.H, {}};
  for_each_effect([&]<class E>() {
    if constexpr (requires { E::magnetometer(filter.view(E::spec.effect), t); }) {
      t.slice = L.of(E::spec.effect);
      E::magnetometer(filter.view(E::spec.effect), t);
    }
  });
  m.R = Eigen::Matrix3d::Identity() * (sigma_uT * sigma_uT);
  return m;
}

}  // namespace sinu::est
