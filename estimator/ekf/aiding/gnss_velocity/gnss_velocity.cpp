#include "estimator/ekf/aiding/gnss_velocity/gnss_velocity.hpp"

#include "estimator/ekf/effects/effect_list.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

namespace {

/// What an effect's gnss_velocity() hook sees and writes (effects/*.hpp).
struct GnssVelocityTerms {
  const NavState& nav;
  const Eigen::Matrix3d& C;        // C_nb
  const Eigen::Vector3d& w_b;      // compensated body rate
  const Eigen::Vector3d& accel_n;      // smoothed NED acceleration
  const Eigen::Vector3d& lag_accel_n;  // mean NED acceleration over the velocity's own lag
  MeasJacobian& H;
  Eigen::Index att;
  Eigen::Vector3d antenna_velocity_n;  // antenna minus IMU velocity, NED (from zero)
  Slice slice;
};

}  // namespace

Measurement gnss_velocity_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                      const Eigen::Vector3d& w_b, const Eigen::Vector3d& accel_n,
                                      const Eigen::Vector3d& lag_accel_n, double dt_back, const GnssObservation& z,
                                      double gate_sigma) {
  const StateLayout& L = filter.layout();
  const Eigen::Matrix3d C = nav.C_nb();
  Measurement m;
  m.gate_sigma = gate_sigma;
  m.H = MeasJacobian::Zero(2, L.dim);
  m.H.block(0, L.vel.start, 2, 3) = Eigen::Matrix<double, 2, 3>::Identity();
  GnssVelocityTerms t{nav, C, w_b, accel_n, lag_accel_n, m.H, L.att.start, Eigen::Vector3d::Zero(), {}};
  for_each_effect([&]<class E>() {
    if constexpr (requires { E::gnss_velocity(filter.view(E::spec.effect), t); }) {
      t.slice = L.of(E::spec.effect);
      E::gnss_velocity(filter.view(E::spec.effect), t);
    }
  });
  const Eigen::Vector3d predicted = nav.v_n_m_s + t.antenna_velocity_n - accel_n * dt_back;
  m.innovation = predicted.head<2>() - z.v_ne_m_s;
  m.R = MeasMat::Identity(2, 2) * (z.sigma_vel_m_s * z.sigma_vel_m_s);
  return m;
}

}  // namespace sinu::est
