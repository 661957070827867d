// Every IMU effect of the vocabulary: its columns of the EKF's state
// transition against finite differences of what the effect does, i.e. the
// filter's own IMU compensation followed by the strapdown step (an independent
// implementation of the motion: a wrong sign, axis or index in a Jacobian
// shows here, whatever effect it belongs to).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ins/strapdown.hpp"

namespace sinu::est {
namespace {

// The effects that act on the IMU samples (the rest act on measurements).
constexpr Effect kImuEffects[] = {Effect::AccelScale,    Effect::GyroScale,    Effect::AccelTempBias,
                                  Effect::GyroTempBias,  Effect::AccelBias,    Effect::GyroBias,
                                  Effect::AccelMisalign, Effect::GyroMisalign, Effect::GyroGSensitivity};

bool acts_on_accel(Effect e) {
  return e == Effect::AccelScale || e == Effect::AccelTempBias || e == Effect::AccelBias || e == Effect::AccelMisalign;
}

NavState moving_state() {
  NavState nav;
  nav.lat_rad = 0.7;
  nav.lon_rad = 0.2;
  nav.h_m = 300.0;
  nav.v_n_m_s = Eigen::Vector3d(30.0, -10.0, 1.0);
  nav.q_nb = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitY()) *
             Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX());
  return nav;
}

// A sample with every axis excited (a coordinated turn with some climb), and a
// temperature away from the reference so the temperature coefficients act.
ImuSample busy_sample() {
  ImuSample s;
  s.specific_force_b_m_s2 = Eigen::Vector3d(1.2, -0.8, -9.6);
  s.angular_rate_b_rad_s = Eigen::Vector3d(0.15, -0.1, 0.3);
  s.temp_degC = 35.0;
  s.has_temp = true;
  return s;
}

// Small-angle attitude error of `computed` against `reference`:
// C_computed = (I - [phi x]) C_reference (state_layout.hpp).
Eigen::Vector3d attitude_error(const NavState& computed, const NavState& reference) {
  const Eigen::Matrix3d M = Eigen::Matrix3d::Identity() - computed.C_nb() * reference.C_nb().transpose();
  return Eigen::Vector3d(0.5 * (M(2, 1) - M(1, 2)), 0.5 * (M(0, 2) - M(2, 0)), 0.5 * (M(1, 0) - M(0, 1)));
}

TEST(EffectJacobians, EveryImuEffectColumnMatchesTheCompensationAndTheStrapdownStep) {
  // A short step: the transition is first order in dt, the strapdown step is
  // not (rotation of f during the interval ~ |w| dt / 2 = 2e-4 here).
  constexpr double kDt = 1e-3;
  for (const Effect e : kImuEffects) {
    SCOPED_TRACE(spec(e).name);
    EffectSet set;
    set.add(e);
    ErrorStateFilter filter;
    filter.init(StateLayout::make(1, set), SensorNoise{}, EffectTuning{}, NavUncertainty{});
    filter.set_reference_temperature(25.0);
    const ImuSample raw = busy_sample();
    const NavState start = moving_state();

    const BodyRates b0 = filter.compensate(raw);
    NavState reference = start;
    Eigen::Vector3d f_n;
    strapdown_step(reference, b0, b0, kDt, f_n);
    PredictInput in;
    in.nav = &reference;
    in.specific_force_b_m_s2 = b0.specific_force_b_m_s2;
    in.angular_rate_b_rad_s = b0.angular_rate_b_rad_s;
    in.specific_force_n_m_s2 = f_n;
    in.temp_delta_degC = raw.temp_degC - 25.0;
    in.dt_s = kDt;
    StateMat Phi;
    StateVec q;
    filter.build_transition(in, 0, Phi, q);

    const StateLayout& L = filter.layout();
    const Slice& s = L.of(e);
    ASSERT_EQ(s.size, kEffectDims[static_cast<std::size_t>(e)]);
    for (Eigen::Index k = 0; k < s.size; ++k) {
      SCOPED_TRACE(effect_component_name(e, k));
      // Raise the estimate by delta: the error state (true - estimated) falls by delta.
      const double delta = 1e-4 * spec(e).initial_sigma;
      ErrorStateFilter moved = filter;
      StateVec dx = StateVec::Zero(L.dim);
      dx(s.start + k) = delta;
      NavState unused = start;
      moved.feedback(dx, unused);
      const BodyRates b1 = moved.compensate(raw);
      NavState computed = start;
      strapdown_step(computed, b1, b1, kDt, f_n);

      const Eigen::Vector3d dv = computed.v_n_m_s - reference.v_n_m_s;
      const Eigen::Vector3d dphi = attitude_error(computed, reference);
      const Eigen::Vector3d dv_model = -Phi.block(L.vel.start, s.start + k, 3, 1) * delta;
      const Eigen::Vector3d dphi_model = -Phi.block(L.att.start, s.start + k, 3, 1) * delta;
      // The block the effect drives: the model within 0.5 % of the difference
      // (the strapdown step's second-order terms at this dt are ~0.02 %; a
      // wrong sign or axis is 100 % off). The other block: nothing in one step
      // beyond second order (a tilt from the gyro moves v only by f dt dphi / 2).
      const Eigen::Vector3d& driven = acts_on_accel(e) ? dv : dphi;
      const Eigen::Vector3d& driven_model = acts_on_accel(e) ? dv_model : dphi_model;
      if (driven.norm() == 0.0) {
        // A component this sample does not excite (none here: every axis moves).
        ADD_FAILURE() << "component not excited by the test sample";
        continue;
      }
      EXPECT_LT((driven_model - driven).norm(), 5e-3 * driven.norm()) << "finite difference " << driven.transpose()
                                                                      << ", model " << driven_model.transpose();
      const Eigen::Vector3d& other_model = acts_on_accel(e) ? dphi_model : dv_model;
      EXPECT_EQ(other_model.norm(), 0.0);
    }
  }
}

// The compensation itself against the vocabulary's definitions: the
// misalignment and g-sensitivity estimates undo what the simulator's sensor
// model does (measured = (I + M) true; gyro += G f).
TEST(EffectJacobians, CompensationUndoesMisalignmentAndGSensitivity) {
  EffectSet set;
  set.add(Effect::AccelMisalign);
  set.add(Effect::GyroMisalign);
  set.add(Effect::GyroGSensitivity);
  ErrorStateFilter filter;
  filter.init(StateLayout::make(1, set), SensorNoise{}, EffectTuning{}, NavUncertainty{});
  Eigen::Matrix3d Ma, Mg, G;
  Ma << 0, 0.01, -0.004, 0.006, 0, 0.012, -0.008, 0.003, 0;
  Mg << 0, -0.007, 0.009, 0.011, 0, -0.005, 0.004, 0.013, 0;
  G << 3e-4, -1e-4, 5e-5, 8e-5, -2e-4, 1e-4, -6e-5, 9e-5, 2.5e-4;
  const StateLayout& L = filter.layout();
  StateVec dx = StateVec::Zero(L.dim);
  for (Eigen::Index k = 0; k < 6; ++k) {
    const auto [i, j] = kOffDiagonal[static_cast<std::size_t>(k)];
    dx(L.of(Effect::AccelMisalign).start + k) = Ma(i, j);
    dx(L.of(Effect::GyroMisalign).start + k) = Mg(i, j);
  }
  for (Eigen::Index k = 0; k < 9; ++k) dx(L.of(Effect::GyroGSensitivity).start + k) = G(k / 3, k % 3);
  NavState nav;
  filter.feedback(dx, nav);
  for (Eigen::Index k = 0; k < 9; ++k) EXPECT_EQ(filter.effect(Effect::GyroGSensitivity, k), G(k / 3, k % 3));

  const Eigen::Vector3d f_true(2.0, -1.5, -9.3), w_true(0.2, 0.4, -0.3);
  ImuSample raw;
  raw.specific_force_b_m_s2 = (Eigen::Matrix3d::Identity() + Ma) * f_true;
  raw.angular_rate_b_rad_s = (Eigen::Matrix3d::Identity() + Mg) * w_true + G * f_true;
  const BodyRates b = filter.compensate(raw);
  // First-order correction: the residual is second order, |M|^2 |f| ~ 2e-4 * 10.
  EXPECT_LT((b.specific_force_b_m_s2 - f_true).norm(), 3e-3);
  EXPECT_LT((b.angular_rate_b_rad_s - w_true).norm(), 1e-4);
  // Without the correction the error is first order: 0.1 m/s^2 and 3 mrad/s.
  EXPECT_GT((raw.specific_force_b_m_s2 - f_true).norm(), 0.1);
  EXPECT_GT((raw.angular_rate_b_rad_s - w_true).norm(), 3e-3);
}

}  // namespace
}  // namespace sinu::est
