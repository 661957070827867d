#include "estimator/ekf/aiding/magnetometer/magnetometer.hpp"

#include "estimator/ekf/effects/effect_list.hpp"

namespace sinu::est {

namespace {

/// What an effect's magnetometer() hook sees and writes (effects/*.hpp).
struct MagnetometerTerms {
  const Eigen::Matrix3d& C_bn;
  const Eigen::Matrix3d& A;    // body field -> reading: S (I - [theta x]) (mag_axes)
  const Eigen::Matrix3d& S;    // soft iron I + D
  const Eigen::Vector3d& u_b;  // the Earth field in the body frame, C_bn F
  const Eigen::Vector3d& u;    // the same in the magnetometer's axes, (I - [theta x]) u_b
  const Eigen::Vector3d& rate_b;  // the body rate [rad/s]
  double thrust_m_s2;          // the thrust beyond a hover's per unit mass, -f_z - g0
  MeasJacobian& H;
  Slice slice;
};

}  // namespace

Measurement magnetometer_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                     const Eigen::Vector3d& mag_b_uT, const BodyRates& now, double sigma_uT,
                                     double gate_sigma) {
  using Motor = effects::MagMotorInterference;
  using Late = effects::MagLatency;
  const StateLayout& L = filter.layout();
  // The body's attitude when the reading was made (mag_latency's tau ago).
  const Eigen::Matrix3d C_bn = Late::back(filter.view(Late::spec.effect), now.angular_rate_b_rad_s) *
                               nav.C_nb().transpose();
  const Eigen::Matrix3d S = filter.mag_soft_iron(), R = filter.mag_misalignment();
  const Eigen::Matrix3d A = S * R;  // filter.mag_axes()
  const Eigen::Vector3d u_b = C_bn * filter.mag_earth_field_n_uT();
  const Eigen::Vector3d u = R * u_b;
  const double thrust = Motor::thrust_m_s2(now.specific_force_b_m_s2);
  Measurement m;
  m.gate_sigma = gate_sigma;
  const Eigen::Vector3d motor = Motor::reading(filter.view(Motor::spec.effect), thrust);
  m.innovation = S * u + filter.mag_hard_iron_b_uT() + motor - mag_b_uT;
  m.H = MeasJacobian::Zero(3, L.dim);
  MagnetometerTerms t{C_bn, A, S, u_b, u, now.angular_rate_b_rad_s, thrust, m.H, {}};
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
