// The priors on the Earth-field state, the declination (ekf/aiding/declination)
// and the World Magnetic Model's strength and inclination
// (ekf/aiding/field_model): their Jacobians against finite differences over
// the true field F = F_hat + e - [F x] phi (the invariant field error and the
// attitude error, state_layout.hpp), at fields of every kind: steep (high
// latitude), flat (equator), pointing up (south), east or west.
#include <gtest/gtest.h>

#include <cmath>

#include "estimator/ekf/aiding/declination/declination.hpp"
#include "estimator/ekf/aiding/field_model/field_model.hpp"

namespace sinu::test {
namespace {

using namespace sinu::est;

const Eigen::Vector3d kFields[] = {{18.0, 2.0, 50.0}, {36.0, 1.6, 6.7}, {20.0, -8.0, -50.0}, {-5.0, 25.0, 30.0}};

/// A filter whose only effect is the Earth field, estimated at F_hat.
void start_with_field(ErrorStateFilter& filter, const Eigen::Vector3d& F_hat) {
  EffectSet set;
  set.add(Effect::MagEarthField);
  filter.init(StateLayout::make(1, set), SensorNoise{}, EffectTuning{}, NavUncertainty{});
  for (Eigen::Index i = 0; i < 3; ++i) filter.set_effect(Effect::MagEarthField, i, F_hat(i));
}

TEST(Declination, JacobianMatchesFiniteDifferencesOfTheFieldsDirection) {
  for (const Eigen::Vector3d& F_hat : kFields) {
    ErrorStateFilter filter;
    start_with_field(filter, F_hat);
    const Slice field = filter.layout().of(Effect::MagEarthField);
    const double d_model = 0.1;
    const Measurement m = declination_measurement(filter, d_model, 0.03, 5.0);
    const double y0 = m.innovation(0);
    EXPECT_NEAR(y0, std::atan2(F_hat.y(), F_hat.x()) - d_model, 1e-12);
    // y(x) = D(F_hat) - D(F_true): the innovation when the truth differs from the estimate by x.
    constexpr double kStep = 1e-6;
    for (int k = 0; k < 6; ++k) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero(), phi = Eigen::Vector3d::Zero();
      (k < 3 ? e : phi)(k % 3) = kStep * (k < 3 ? F_hat.norm() : 1.0);
      const Eigen::Vector3d F_true = F_hat + e - F_hat.cross(phi);
      const double y = std::atan2(F_hat.y(), F_hat.x()) - std::atan2(F_true.y(), F_true.x());
      const Eigen::Index col = k < 3 ? field.start + k : filter.layout().att.start + (k - 3);
      const double dx = k < 3 ? e(k) : phi(k - 3);
      // Central-difference-free check: first order, the step's square (1e-12) is the error.
      EXPECT_NEAR(m.H(0, col) * dx, y, 1e-10) << "field " << F_hat.transpose() << " state " << k;
    }
  }
}

TEST(FieldModel, JacobianMatchesFiniteDifferencesOfStrengthAndInclination) {
  const Eigen::Vector3d model(20.0, 2.0, 45.0);
  for (const Eigen::Vector3d& F_hat : kFields) {
    ErrorStateFilter filter;
    start_with_field(filter, F_hat);
    const Slice field = filter.layout().of(Effect::MagEarthField);
    const Measurement m = field_model_measurement(filter, model, 5.0, 0.05, 5.0);
    ASSERT_EQ(m.innovation.size(), 2);
    const auto inclination = [](const Eigen::Vector3d& F) { return std::atan2(F.z(), F.head<2>().norm()); };
    EXPECT_NEAR(m.innovation(0), F_hat.norm() - model.norm(), 1e-12);
    EXPECT_NEAR(m.innovation(1), inclination(F_hat) - inclination(model), 1e-12);
    EXPECT_DOUBLE_EQ(m.R(0, 0), 25.0);
    EXPECT_DOUBLE_EQ(m.R(1, 1), 0.0025);
    constexpr double kStep = 1e-6;
    for (int k = 0; k < 6; ++k) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero(), phi = Eigen::Vector3d::Zero();
      (k < 3 ? e : phi)(k % 3) = kStep * (k < 3 ? F_hat.norm() : 1.0);
      const Eigen::Vector3d F_true = F_hat + e - F_hat.cross(phi);
      // y(x) = h(F_hat) - h(F_true): the innovation when the truth differs from the estimate by x.
      const double y[2] = {F_hat.norm() - F_true.norm(), inclination(F_hat) - inclination(F_true)};
      const Eigen::Index col = k < 3 ? field.start + k : filter.layout().att.start + (k - 3);
      const double dx = k < 3 ? e(k) : phi(k - 3);
      for (Eigen::Index r = 0; r < 2; ++r) {
        // First order: the step's square (~1e-12 of the field: 5e-11 uT, 1e-12 rad) is the error.
        EXPECT_NEAR(m.H(r, col) * dx, y[r], 1e-9) << "field " << F_hat.transpose() << " row " << r << " state " << k;
      }
    }
  }
}

// At a magnetic pole the field estimate can be vertical: the inclination's
// row stays finite (no 0 / 0 in its gradient).
TEST(FieldModel, AVerticalFieldGivesAFiniteMeasurement) {
  ErrorStateFilter filter;
  start_with_field(filter, Eigen::Vector3d(0.0, 0.0, 58.0));
  const Measurement m = field_model_measurement(filter, Eigen::Vector3d(20.0, 2.0, 45.0), 5.0, 0.05, 5.0);
  EXPECT_TRUE(m.innovation.allFinite());
  EXPECT_TRUE(m.H.allFinite());
}


// The soft iron's common scale is the Earth field's strength again (S = I + D
// scales S C_bn F): held at zero once, it takes the diagonals' common part
// away and leaves their differences and the off-diagonals, which the field's
// strength cannot mimic. Fused into a filter whose soft iron reads a common
// 0.1 on its diagonals (the trace 0.3) and a difference between them.
TEST(SoftIronScale, TheDiagonalsCommonPartGoesToZeroTheRestStays) {
  ErrorStateFilter filter;
  filter.init(StateLayout::make(1, EffectSet::of({Effect::MagSoftIron})), SensorNoise{}, EffectTuning{},
              NavUncertainty{});
  const double D[6] = {0.12, 0.10, 0.08, 0.06, -0.04, 0.05};  // xx yy zz xy xz yz
  for (Eigen::Index i = 0; i < 6; ++i) filter.set_effect(Effect::MagSoftIron, i, D[i]);
  StateVec dx = StateVec::Zero(filter.layout().dim);
  const StateMask frozen;
  const Measurement m = soft_iron_scale_measurement(filter, 1e-3, 1e9);
  EXPECT_DOUBLE_EQ(m.innovation(0), 0.30);
  NavState nav;
  ASSERT_TRUE(fuse_measurement(filter.P(), dx, m, frozen).accepted);
  filter.feedback(dx, nav);
  const EffectView v = filter.view(Effect::MagSoftIron);
  // The common part (0.1 each) removed to the measurement's 1e-3; equal
  // priors take it from the three alike, so the differences stay.
  EXPECT_NEAR(v.v[0] + v.v[1] + v.v[2], 0.0, 2e-3);
  EXPECT_NEAR(v.v[0] - v.v[1], 0.02, 1e-9);
  EXPECT_NEAR(v.v[1] - v.v[2], 0.02, 1e-9);
  for (int i = 3; i < 6; ++i) EXPECT_DOUBLE_EQ(v.v[i], D[i]) << i;
}

}  // namespace
}  // namespace sinu::test
