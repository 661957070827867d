// The non-holonomic constraint's rows for velocity and attitude against
// finite differences of its measurement function, for the contract's axes
// (y, z), a unit mounted sideways (x, z) and one turned 30 deg and tilted
// 8 deg on its bracket (axes off every body axis). With
// dv = v_hat - v and C_nb_hat = (I - [phi x]) C_nb the innovation moves by
// +H [dv; phi].
#include <gtest/gtest.h>

#include "estimator/ekf/aiding/nonholonomic/nonholonomic.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {
namespace {

TEST(Nonholonomic, VelocityAndAttitudeRowsMatchFiniteDifferencesForAnyMount) {
  ErrorStateFilter filter;
  filter.init(StateLayout::make(1, EffectSet{}), SensorNoise{}, EffectTuning{}, NavUncertainty{});
  const StateLayout& L = filter.layout();
  NavState nav;
  nav.v_n_m_s = Eigen::Vector3d(9.0, -4.0, 0.3);
  nav.q_nb = Eigen::AngleAxisd(0.8, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.04, Eigen::Vector3d::UnitY()) *
             Eigen::AngleAxisd(-0.03, Eigen::Vector3d::UnitX());
  const Eigen::Vector3d w_b(0.01, -0.02, 0.1);
  const Eigen::Matrix3d tilted = (Eigen::AngleAxisd(0.5236, Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(0.14, Eigen::Vector3d::UnitY())).toRotationMatrix();
  const VehicleAxes mounts[] = {VehicleAxes{}, VehicleAxes{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ()},
                                VehicleAxes{tilted.col(1), tilted.col(2)}};
  for (const VehicleAxes& axes : mounts) {
    SCOPED_TRACE(axes.lateral_b.transpose());
    const Measurement m0 = nonholonomic_measurement(filter, nav, w_b, NonholonomicConfig{}, 5.0, axes);
    // The rows measure the body velocity along the vehicle's lateral and vertical axes.
    const Eigen::Vector3d v_b = nav.C_nb().transpose() * nav.v_n_m_s;
    EXPECT_DOUBLE_EQ(m0.innovation(0), axes.lateral_b.dot(v_b));
    EXPECT_DOUBLE_EQ(m0.innovation(1), axes.vertical_b.dot(v_b));
    constexpr double kStep = 1e-6;
    for (Eigen::Index k = 0; k < 3; ++k) {
      NavState moved = nav;
      moved.v_n_m_s(k) += kStep;
      const Eigen::Vector2d dy = (nonholonomic_measurement(filter, moved, w_b, NonholonomicConfig{}, 5.0, axes).innovation -
                                  m0.innovation).head<2>();
      // Linear in v: only rounding (1e-16 of 10 over 1e-6) separates them.
      EXPECT_LT((dy - m0.H.block(0, L.vel.start + k, 2, 1) * kStep).norm(), 1e-8 * kStep);
      Eigen::Vector3d phi = Eigen::Vector3d::Zero();
      phi(k) = kStep;
      moved = nav;
      moved.q_nb = (quat_from_rotation_vector(-phi) * nav.q_nb).normalized();  // I - [phi x], first order
      const Eigen::Vector2d da = (nonholonomic_measurement(filter, moved, w_b, NonholonomicConfig{}, 5.0, axes).innovation -
                                  m0.innovation).head<2>();
      // First order in phi: the residual is |v| phi^2 ~ 1e-11, far below |H phi| ~ 1e-5.
      EXPECT_LT((da - m0.H.block(0, L.att.start + k, 2, 1) * kStep).norm(), 1e-3 * da.norm() + 1e-10);
    }
  }
}

}  // namespace
}  // namespace sinu::est
