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

namespace sinu::est {
namespace {

// The vehicle_mount state: reserved until a bracket is found, then started
// as the heading's error (fully correlated with the attitude about the
// vertical, plus its own sigma); its estimate turns the lateral axis, and its
// column matches finite differences of the measurement in that estimate
// (state = true - estimate: raising the estimate by e moves the innovation by -H e).
TEST(Nonholonomic, TheVehicleMountStartsAsTheHeadingsErrorAndItsColumnMatchesFiniteDifferences) {
  ErrorStateFilter filter;
  const EffectSet mount = EffectSet::of({Effect::VehicleMount});
  filter.init(StateLayout::make(1, mount, mount), SensorNoise{}, EffectTuning{}, NavUncertainty{});
  ASSERT_FALSE(filter.layout().has(Effect::VehicleMount));
  ASSERT_TRUE(filter.layout().carries(Effect::VehicleMount));
  filter.start_vehicle_mount(0.035);
  const StateLayout& L = filter.layout();
  ASSERT_TRUE(L.has(Effect::VehicleMount));
  const Eigen::Index m = L.of(Effect::VehicleMount).start, yaw = L.att.start + 2;
  EXPECT_DOUBLE_EQ(filter.P()(m, yaw), filter.P()(yaw, yaw));
  EXPECT_DOUBLE_EQ(filter.P()(m, m), filter.P()(yaw, yaw) + 0.035 * 0.035);
  EXPECT_DOUBLE_EQ(filter.P()(m, L.vel.start), filter.P()(yaw, L.vel.start));

  NavState nav;
  nav.v_n_m_s = Eigen::Vector3d(9.0, -4.0, 0.3);
  nav.q_nb = Eigen::AngleAxisd(0.8, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.04, Eigen::Vector3d::UnitY());
  const Eigen::Matrix3d tilted = (Eigen::AngleAxisd(0.5236, Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(0.14, Eigen::Vector3d::UnitY())).toRotationMatrix();
  const VehicleAxes found{tilted.col(1), tilted.col(2)};
  const Eigen::Vector3d w_b(0.01, -0.02, 0.1), v_b = nav.C_nb().transpose() * nav.v_n_m_s;
  filter.set_effect(Effect::VehicleMount, 0, 0.2);
  const Measurement m0 = nonholonomic_measurement(filter, nav, w_b, NonholonomicConfig{}, 5.0, found);
  EXPECT_DOUBLE_EQ(m0.innovation(0), found.turned(0.2).lateral_b.dot(v_b));
  EXPECT_DOUBLE_EQ(m0.innovation(1), found.vertical_b.dot(v_b));  // a turn about the vertical leaves it
  // The unit turned 0.2 rad further: the vehicle's lateral axis gains that much of its forward one.
  EXPECT_NEAR((found.turned(0.2).lateral_b - (std::cos(0.2) * found.lateral_b + std::sin(0.2) * found.forward_b())).norm(),
              0.0, 1e-12);
  constexpr double kStep = 1e-6;
  filter.set_effect(Effect::VehicleMount, 0, 0.2 + kStep);
  const Eigen::Vector2d dy =
      (nonholonomic_measurement(filter, nav, w_b, NonholonomicConfig{}, 5.0, found).innovation - m0.innovation).head<2>();
  // Smooth in the angle: the residual is |v| e^2 ~ 1e-11 against |H e| ~ 1e-5.
  EXPECT_LT((dy + m0.H.block(0, m, 2, 1) * kStep).norm(), 1e-3 * dy.norm() + 1e-10);
  // The lateral row sees the mount by the speed along the vehicle's forward axis.
  EXPECT_NEAR(m0.H(0, m), -found.turned(0.2).forward_b().dot(v_b), 1e-12);
  EXPECT_EQ(m0.H(1, m), 0.0);
}

}  // namespace
}  // namespace sinu::est
