// Every effect of the vocabulary against finite differences of what it does:
// an IMU effect's columns of the EKF's state transition against the filter's
// own IMU compensation followed by the strapdown step (an independent
// implementation of the motion), and every effect's columns of every aiding
// source's Jacobian against the measurement function itself. A wrong sign,
// axis or index in a Jacobian shows here, whatever effect it belongs to.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include <string>
#include <vector>

#include "estimator/ekf/effects/effect_list.hpp"
#include "estimator/ekf/aiding/gnss_position/gnss_position.hpp"
#include "estimator/ekf/aiding/gnss_velocity/gnss_velocity.hpp"
#include "estimator/ekf/aiding/magnetometer/magnetometer.hpp"
#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ins/strapdown.hpp"

namespace sinu::est {
namespace {

// The effects that act on the IMU samples (an IMU correction in their file;
// the rest act on measurements), from the registration itself: a new effect
// is tested here without a line of this file changing.
std::vector<Effect> imu_effects() {
  std::vector<Effect> out;
  for_each_effect([&]<class E>() {
    if constexpr (requires { E::stage; }) out.push_back(E::spec.effect);
  });
  return out;
}

bool acts_on_accel(Effect e) { return spec(e).triad == Triad::Accel; }

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
  const std::vector<Effect> effects = imu_effects();
  ASSERT_EQ(effects.size(), 9u);  // scale, temperature, bias, misalignment x accel/gyro, g-sensitivity
  for (const Effect e : effects) {
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

namespace sinu::est {
namespace {

// Every effect's columns of every aiding source's Jacobian against finite
// differences of the measurement function: raise the effect's estimate by
// delta, the error state (true - estimated) falls by delta, so the innovation
// (h(x_hat) - z) moves by -H delta. Every effect's value is set away from zero
// so that products (soft iron times field, lever arm times rate) are excited.
// The latency enters through the time the fix is taken back by (dt_back).
struct SourceCase {
  const char* name;
  EffectSet needs;  // states the source needs besides the effect under test
  Measurement (*build)(const ErrorStateFilter&, const NavState&, double dt_back);
};

GnssObservation a_fix(const NavState& nav) {
  GnssObservation z;
  z.has_position = z.has_velocity = true;
  z.lat_rad = nav.lat_rad + 2e-7;
  z.lon_rad = nav.lon_rad - 1e-7;
  z.h_m = nav.h_m + 1.5;
  z.sigma_ned_m = Eigen::Vector3d(1.0, 1.2, 2.0);
  z.v_ne_m_s = nav.v_n_m_s.head<2>() + Eigen::Vector2d(0.1, -0.2);
  return z;
}

const SourceCase kSources[] = {
    {"gnss_position", {},
     [](const ErrorStateFilter& f, const NavState& nav, double dt_back) {
       return gnss_position_measurement(f, nav, dt_back, a_fix(nav), 5.0);
     }},
    {"gnss_velocity", {},
     [](const ErrorStateFilter& f, const NavState& nav, double dt_back) {
       return gnss_velocity_measurement(f, nav, Eigen::Vector3d(0.15, -0.1, 0.3), Eigen::Vector3d(1.0, -2.0, 0.5),
                                        Eigen::Vector3d(0.7, -1.6, 0.4), dt_back, a_fix(nav), 5.0);
     }},
    {"magnetometer", [] {
       EffectSet s;
       s.add(Effect::MagEarthField);
       return s;
     }(),
     [](const ErrorStateFilter& f, const NavState& nav, double) {
       // A climb's thrust, 1.9 m/s^2 beyond a hover's (mag_motor_interference's input), in a
       // turn (mag_latency's).
       const BodyRates now{Eigen::Vector3d(0.4, -0.3, -11.7), Eigen::Vector3d(0.2, -0.1, 0.5)};
       return magnetometer_measurement(f, nav, Eigen::Vector3d(20.0, -5.0, 40.0), now, 0.5, 5.0);
     }},
};

TEST(EffectJacobians, EveryAidingSourceColumnOfEveryEffectMatchesItsMeasurementFunction) {
  int columns_checked = 0;
  for (const SourceCase& src : kSources) {
    for (std::size_t ei = 0; ei < kEffectCount; ++ei) {
      const auto e = static_cast<Effect>(ei);
      SCOPED_TRACE(std::string(src.name) + " x " + spec(e).name);
      EffectSet set = src.needs;
      set.add(e);
      ErrorStateFilter filter;
      filter.init(StateLayout::make(1, set), SensorNoise{}, EffectTuning{}, NavUncertainty{});
      // Every value away from zero: a quarter of its plausible maximum, varied by component.
      for (std::size_t j = 0; j < kEffectCount; ++j) {
        const auto ej = static_cast<Effect>(j);
        for (Eigen::Index k = 0; k < kEffectDims[j]; ++k)
          filter.set_effect(ej, k, 0.25 * spec(ej).plausible_max * (1.0 - 0.3 * static_cast<double>(k)));
      }
      for (Eigen::Index k = 0; k < 3; ++k)
        filter.set_effect(Effect::MagEarthField, k, Eigen::Vector3d(22.0, 3.0, 41.0)(k));
      const NavState nav = moving_state();
      const double dt_back = 0.05;
      const Measurement m0 = src.build(filter, nav, dt_back);
      const Slice& s = filter.layout().of(e);
      for (Eigen::Index k = 0; k < s.size; ++k) {
        SCOPED_TRACE(effect_component_name(e, k));
        const double delta = 1e-5 * spec(e).initial_sigma;
        ErrorStateFilter moved = filter;
        moved.set_effect(e, k, filter.effect(e, k) + delta);
        const double moved_back = e == Effect::GpsLatency ? dt_back + delta : dt_back;
        const Measurement m1 = src.build(moved, nav, moved_back);
        const MeasVec dy = m1.innovation - m0.innovation;
        const MeasVec dy_model = -m0.H.col(s.start + k) * delta;
        // First order: the measurement functions are at most quadratic in one
        // effect's value over delta (1e-5 of its prior): 1e-4 relative, plus
        // the innovation's rounding (~1e-16 of ~1e2).
        EXPECT_LT((dy_model - dy).norm(), 1e-4 * dy.norm() + 1e-12)
            << "finite difference " << dy.transpose() << ", model " << dy_model.transpose();
        ++columns_checked;
      }
    }
  }
  // Every state of every effect, for every source: most columns are zero (an
  // effect a source does not see), and the test checks they are.
  EXPECT_EQ(columns_checked, 3 * static_cast<int>(kMaxEffectStates));
}

}  // namespace
}  // namespace sinu::est
