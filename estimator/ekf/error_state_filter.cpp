#include "estimator/ekf/error_state_filter.hpp"

#include <algorithm>
#include <cmath>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ekf/covariance.hpp"
#include "estimator/ekf/effects/effect_list.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

namespace {

// What effects/*.hpp see of the filter, one struct per hook.

/// The IMU sample being compensated (compensate()).
struct ImuSignals {
  Eigen::Vector3d accel_offset, gyro_offset;  // bias-like terms, the sensor states' to start
  Eigen::Vector3d accel_temp_offset = Eigen::Vector3d::Zero(), gyro_temp_offset = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel, gyro;  // after the offsets: scaled, crossed, coupled in turn
  double dT = 0.0;              // temperature minus the reference
};

/// One interval's error dynamics (build_transition): an effect adds its
/// states' columns to the velocity or attitude rows.
struct TransitionTerms {
  static constexpr int kMaxCols = static_cast<int>(kMaxStates);
  const Eigen::Matrix3d& C;    // C_nb
  const Eigen::Vector3d& f_b;  // compensated specific force, mid-interval
  const Eigen::Vector3d& w_b;  // compensated rate, mid-interval
  double dT, dt;
  StateMat& Phi;
  Eigen::Index V, A;  // velocity and attitude rows
  Slice slice;        // the effect's states
  template <class M> void add_velocity(Eigen::Index k, const M& cols) {
    Phi.block(V, slice.start + k, 3, cols.cols()) += cols;
  }
  template <class M> void add_attitude(Eigen::Index k, const M& cols) {
    Phi.block(A, slice.start + k, 3, cols.cols()) += cols;
  }
};

/// Process noise and own dynamics of an effect's states.
struct NoiseTerms {
  const SensorNoise& noise;
  const EffectTuning& tuning;
  const Eigen::Vector3d& gps_bias_sigma_ned_m;
  double dt;
  StateMat& Phi;
  StateVec& q;
  Slice slice;
  /// A random walk of this density on every state of the effect (none when not positive).
  void walk(double density) {
    if (!(density > 0.0)) return;
    q.segment(slice.start, slice.size).setConstant(density * density * dt);
  }
};

/// The estimate's own propagation over an interval.
struct MeanTerms {
  const EffectTuning& tuning;
  double dt;
};

}  // namespace

/// A correction being fed back (feedback()).
struct ErrorStateFilter::FeedbackTerms {
  ErrorStateFilter& filter;
  const StateVec& dx;
  Slice att;
  Slice slice;
  /// The attitude correction as a rotation of the navigation frame.
  Eigen::Matrix3d attitude_rotation() const {
    return quat_from_rotation_vector(dx.segment(att.start, 3)).toRotationMatrix();
  }
  /// P <- G P G^T for a 3-state block: a reset Jacobian.
  void rotate_block(const Slice& block, const Eigen::Matrix3d& G) { filter.rotate_block(block, G); }
};

void ErrorStateFilter::init(const StateLayout& layout, const SensorNoise& noise, const EffectTuning& tuning,
                            const NavUncertainty& nav0) {
  layout_ = layout;
  noise_ = noise;
  tuning_ = tuning;
  const Eigen::Index n = layout.dim;
  P_ = StateMat::Zero(n, n);
  P_.block(layout.pos.start, layout.pos.start, 3, 3) = nav0.pos_ned_m.cwiseAbs2().asDiagonal();
  P_.block(layout.vel.start, layout.vel.start, 3, 3) = nav0.vel_ned_m_s.cwiseAbs2().asDiagonal();
  P_.block(layout.att.start, layout.att.start, 3, 3) = nav0.att_rad.cwiseAbs2().asDiagonal();
  const Eigen::Index p = layout.order;
  for (Eigen::Index axis = 0; axis < kSensorAxes; ++axis) {
    const auto k = static_cast<std::size_t>(axis);
    ar_step_[k] = noise.kind == NoiseModelKind::AutoRegressive ? ar_companion(noise.ar[k], p) : AxisBlock::Identity(1, 1);
    AxisBlock X = stationary_covariance(noise, axis, p);
    if (!X.allFinite()) X = AxisBlock::Identity(p, p) * 1.0;  // unstable model: wide, honest prior
    P_.block(layout.sensor_state(axis), layout.sensor_state(axis), p, p) = X;
  }
  for (std::size_t i = 0; i < kEffectCount; ++i) {
    const Slice& s = layout.effect[i];
    const double sig = tuning.initial_sigma[i];
    for (Eigen::Index j = 0; j < s.size; ++j) P_(s.start + j, s.start + j) = sig * sig;
  }
  gps_bias_sigma_ned_m_ = Eigen::Vector3d::Constant(tuning.sigma(Effect::GpsPositionBias));
  gps_white_fraction_ned_ = Eigen::Vector3d::Constant(1.0 - tuning.gps_bias_variance_fraction);
  value_.fill(0.0);
  sensor_hat_ = StateVec::Zero(layout.sensor.size);
  ar_clock_s_ = 0.0;
}

void ErrorStateFilter::reanchor_hard_iron(const NavState& nav, const Eigen::Vector3d& mag_b_uT, double sigma_uT) {
  if (!layout_.has(Effect::MagHardIron)) return;
  const Eigen::Vector3d predicted = mag_axes() * (nav.C_nb().transpose() * mag_earth_field_n_uT());
  const Eigen::Vector3d h = mag_b_uT - predicted;
  for (Eigen::Index i = 0; i < 3; ++i) set_effect(Effect::MagHardIron, i, h(i));
  const Slice& H = layout_.of(Effect::MagHardIron);
  const double keep = std::sqrt(P_.block(H.start, H.start, 3, 3).diagonal().maxCoeff());
  reset_block(H, Eigen::Vector3d::Constant(std::hypot(sigma_uT, keep)));
}

Eigen::Vector3d ErrorStateFilter::mag_field_b_uT(const Eigen::Vector3d& mag_b_uT) const {
  static const std::array<EffectPrior, kEffectCount> kNothingElse{};
  return mag_field_b_uT(mag_b_uT, kNothingElse);
}

Eigen::Vector3d ErrorStateFilter::mag_field_b_uT(const Eigen::Vector3d& mag_b_uT,
                                                 const std::array<EffectPrior, kEffectCount>& instead) const {
  std::array<double, kMaxEffectStates> known = value_;  // a deferred state at its given prior
  const auto at = [&](Effect e) { return known.data() + kEffectValueOffset[static_cast<std::size_t>(e)]; };
  for (const Effect e : {Effect::MagHardIron, Effect::MagSoftIron, Effect::MagMisalign}) {
    const EffectPrior& given = tuning_.prior[static_cast<std::size_t>(e)];
    const EffectPrior& other = instead[static_cast<std::size_t>(e)];
    const EffectPrior& p = other.given ? other : given;
    if (other.given || (p.given && !layout_.has(e)))
      std::copy_n(p.value.begin(), kEffectDims[static_cast<std::size_t>(e)], at(e));
  }
  const Eigen::Matrix3d A = mag_axes_of(EffectView{at(Effect::MagSoftIron)}, EffectView{at(Effect::MagMisalign)});
  return A.inverse() * (mag_b_uT - EffectView{at(Effect::MagHardIron)}.vec3());
}

void ErrorStateFilter::activate_deferred(EffectSet which) {
  if (!layout_.has_deferred(which)) return;
  const Eigen::Index n = layout_.dim;
  const StateLayout before = layout_;
  layout_.activate(which);
  const StateMat old = P_;
  P_ = StateMat::Zero(layout_.dim, layout_.dim);
  P_.topLeftCorner(n, n) = old.topLeftCorner(n, n);
  for (std::size_t i = 0; i < kEffectCount; ++i) {
    const Slice& s = layout_.effect[i];
    if (before.effect[i].active() || !s.active()) continue;
    const double sig = tuning_.initial_sigma[i];
    for (Eigen::Index j = 0; j < s.size; ++j) P_(s.start + j, s.start + j) = sig * sig;
    apply_prior(static_cast<Effect>(i));
  }
}

void ErrorStateFilter::start_vehicle_mount(double independent_sigma_rad) {
  if (layout_.has(Effect::VehicleMount)) return;
  activate_deferred(EffectSet::of({Effect::VehicleMount}));
  if (!layout_.has(Effect::VehicleMount)) return;
  // Found = true yaw on the vehicle + the heading's error e; with
  // C_nb_hat = (I - [phi x]) C_nb, e = -phi_z, and the state (true - found) is phi_z.
  const Eigen::Index m = layout_.of(Effect::VehicleMount).start, yaw = layout_.att.start + 2;
  set_effect(Effect::VehicleMount, 0, 0.0);
  P_.row(m) = P_.row(yaw);
  P_.col(m) = P_.col(yaw);
  P_(m, m) = P_(yaw, yaw) + independent_sigma_rad * independent_sigma_rad;
}

void ErrorStateFilter::build_transition(const PredictInput& in, int ar_steps, StateMat& Phi, StateVec& q) const {
  const StateLayout& L = layout_;
  const NavState& nav = *in.nav;
  const double dt = in.dt_s;
  const Eigen::Index n = L.dim;
  Phi = StateMat::Identity(n, n);
  q = StateVec::Zero(n);
  const Eigen::Matrix3d C = nav.C_nb();
  const Eigen::Vector3d w_ie = wgs84::omega_ie_n(nav.lat_rad);
  const Eigen::Vector3d w_en = wgs84::omega_en_n(nav.lat_rad, nav.h_m, nav.v_n_m_s);
  const double g = wgs84::normal_gravity_m_s2(nav.lat_rad, nav.h_m);
  const double r = std::sqrt(wgs84::meridian_radius_m(nav.lat_rad) * wgs84::transverse_radius_m(nav.lat_rad)) + nav.h_m;
  const Eigen::Index P = L.pos.start, V = L.vel.start, A = L.att.start;

  Phi.block(P, V, 3, 3) += Eigen::Matrix3d::Identity() * dt;
  Phi(V + 2, P + 2) += 2.0 * g / r * dt;  // gravity falls with height: d_g_down = +2g/R d_p_down
  Phi.block(V, V, 3, 3) -= skew(2.0 * w_ie + w_en) * dt;
  Phi.block(V, A, 3, 3) += skew(in.specific_force_n_m_s2) * dt;
  Phi.block(A, A, 3, 3) -= skew(w_ie + w_en) * dt;
  for (Eigen::Index i = 0; i < 3; ++i) {
    Phi.block(V, L.sensor_state(sensor_axis::kFirstAccel + i), 3, 1) += C.col(i) * dt;
    Phi.block(A, L.sensor_state(sensor_axis::kFirstGyro + i), 3, 1) -= C.col(i) * dt;
  }
  // Each effect's columns (effects/*.hpp), the magnetometer's field last: it
  // follows the attitude rows the others have written.
  TransitionTerms t{C, in.specific_force_b_m_s2, in.angular_rate_b_rad_s, in.temp_delta_degC, dt, Phi, V, A, {}};
  for_each_effect([&]<class E>() {
    if constexpr (requires { E::couple(view(E::spec.effect), t); }) {
      if (!L.has(E::spec.effect)) return;
      t.slice = L.of(E::spec.effect);
      E::couple(view(E::spec.effect), t);
    }
  });
  for_each_effect([&]<class E>() {
    if constexpr (requires { E::couple_last(view(E::spec.effect), t); }) {
      if (!L.has(E::spec.effect)) return;
      t.slice = L.of(E::spec.effect);
      E::couple_last(view(E::spec.effect), t);
    }
  });

  // White noise: the model's, or what the data show when that is more (vibration).
  const double na = std::max(noise_.accel_white_m_s2_rthz, in.accel_white_floor_m_s2_rthz);
  const double ng = std::max(noise_.gyro_white_rad_s_rthz, in.gyro_white_floor_rad_s_rthz);
  q.segment(V, 3).setConstant(na * na * dt);
  q.segment(A, 3).setConstant(ng * ng * dt);

  const Eigen::Index p = L.order;
  for (Eigen::Index axis = 0; axis < kSensorAxes; ++axis) {
    const auto k = static_cast<std::size_t>(axis);
    const Eigen::Index s = L.sensor_state(axis);
    if (noise_.kind == NoiseModelKind::GaussMarkov) {
      const double phi = std::exp(-dt / noise_.gm[k].tau_s);
      Phi(s, s) = phi;
      q(s) = noise_.gm[k].variance * (1.0 - phi * phi);
    } else if (ar_steps > 0) {
      AxisBlock F = AxisBlock::Identity(p, p);
      for (int i = 0; i < ar_steps; ++i) F = (ar_step_[k] * F).eval();
      Phi.block(s, s, p, p) = F;
      q(s) = noise_.ar[k].variance * ar_steps;
    }
  }
  for (std::size_t i = 0; i < kEffectCount; ++i) {
    const Slice& sl = L.effect[i];
    for (Eigen::Index j = 0; j < sl.size; ++j) q(sl.start + j) = tuning_.random_walk[i] * tuning_.random_walk[i] * dt;
  }
  // Effects with dynamics of their own (a walk from the sensor model, a GM process).
  NoiseTerms nt{noise_, tuning_, gps_bias_sigma_ned_m_, dt, Phi, q, {}};
  for_each_effect([&]<class E>() {
    if constexpr (requires { E::process_noise(view(E::spec.effect), nt); }) {
      if (!L.has(E::spec.effect)) return;
      nt.slice = L.of(E::spec.effect);
      E::process_noise(view(E::spec.effect), nt);
    }
  });
}

void ErrorStateFilter::predict(const PredictInput& in) {
  int ar_steps = 0;
  if (noise_.kind == NoiseModelKind::AutoRegressive) {
    ar_clock_s_ += in.dt_s;
    const double period = noise_.ar_sample_period_s;
    while (ar_clock_s_ >= period * (1.0 - 1e-6)) {  // tolerance: IMU time stamps jitter by microseconds
      ar_clock_s_ -= period;
      ++ar_steps;
    }
  }
  StateMat Phi;
  StateVec q;
  build_transition(in, ar_steps, Phi, q);
  propagate_covariance(P_, Phi, q);
  if (layout_.has(Effect::MagEarthField)) {
    // The attitude's white noise reaches the invariant field error too (e += [F x] w).
    const Slice& A = layout_.att;
    const double qa = q(A.start);
    add_field_coupled_noise(Eigen::Matrix3d::Identity() * qa, /*attitude_block_too=*/false);
  }
  // Mean of the sensor-error states follows the same linear dynamics.
  const Eigen::Index S = layout_.sensor.start;
  const Eigen::Index m = layout_.sensor.size;
  sensor_hat_ = (Phi.block(S, S, m, m) * sensor_hat_).eval();
  const MeanTerms mt{tuning_, in.dt_s};
  for_each_effect([&]<class E>() {
    if constexpr (requires(double* v) { E::predict_mean(v, mt); }) {
      if (layout_.has(E::spec.effect)) E::predict_mean(values(E::spec.effect), mt);
    }
  });
}

void ErrorStateFilter::start_mag_field(const NavState& nav, const Eigen::Vector3d& mag_b_uT, double noise_sigma_uT) {
  const Eigen::Matrix3d C = nav.C_nb();
  const Eigen::Vector3d F_n = C * mag_axes().inverse() * (mag_b_uT - mag_hard_iron_b_uT());
  for (Eigen::Index i = 0; i < 3; ++i) set_effect(Effect::MagEarthField, i, F_n(i));
  if (!layout_.has(Effect::MagEarthField)) return;
  // F = C (m - h - n) and F_hat = C_hat (m - h_hat), C_hat = (I - [phi x]) C, so with
  // dh = h - h_hat: dF = -[F x] phi - C dh - C n, and the invariant error
  // e = dF + [F x] phi = -C dh - C n, uncorrelated with the attitude:
  // P_e,x = -C P_h,x, P_ee = C P_hh C^T + noise. (The first innovation is then
  // the sensor noise alone: one sample teaches nothing yet.)
  const Eigen::Index F = layout_.of(Effect::MagEarthField).start;
  P_.middleRows(F, 3).setZero();
  P_.middleCols(F, 3).setZero();
  Eigen::Matrix3d Pee = Eigen::Matrix3d::Identity() * (noise_sigma_uT * noise_sigma_uT);
  if (layout_.has(Effect::MagHardIron)) {
    const Eigen::Index H = layout_.of(Effect::MagHardIron).start;
    const StateMat row = -C * P_.middleRows(H, 3);  // 3 x n
    P_.middleRows(F, 3) = row;
    P_.middleCols(F, 3) = row.transpose();
    Pee -= row.middleCols(H, 3) * C.transpose();
  }
  P_.block(F, F, 3, 3) = 0.5 * (Pee + Pee.transpose());
}

void ErrorStateFilter::feedback(StateVec& dx, NavState& nav) {
  const StateLayout& L = layout_;
  nav.move_position_m(-dx.segment(L.pos.start, 3));
  nav.v_n_m_s -= dx.segment(L.vel.start, 3);
  nav.q_nb = (quat_from_rotation_vector(dx.segment(L.att.start, 3)) * nav.q_nb).normalized();
  sensor_hat_ += dx.segment(L.sensor.start, L.sensor.size);
  FeedbackTerms t{*this, dx, L.att, {}};
  for_each_effect([&]<class E>() {
    if (!L.has(E::spec.effect)) return;
    double* v = values(E::spec.effect);
    t.slice = L.of(E::spec.effect);
    if constexpr (requires { E::feedback(v, t); }) {
      E::feedback(v, t);
    } else {
      for (Eigen::Index i = 0; i < t.slice.size; ++i) v[i] += dx(t.slice.start + i);
    }
  });
  dx.setZero();
}

BodyRates ErrorStateFilter::compensate(const ImuSample& raw) const {
  ImuSignals sig;
  sig.dT = raw.has_temp ? raw.temp_degC - temp_ref_degC_ : 0.0;
  for (Eigen::Index i = 0; i < 3; ++i) {
    sig.accel_offset(i) = sensor_hat_(hat_index(sensor_axis::kFirstAccel + i));
    sig.gyro_offset(i) = sensor_hat_(hat_index(sensor_axis::kFirstGyro + i));
  }
  // Every effect with an IMU correction, stage by stage (effect_spec.hpp's ImuStage):
  // values of effects without states are zero, the nominal sensor.
  const auto stage = [&](ImuStage which) {
    for_each_effect([&]<class E>() {
      if constexpr (requires { E::stage; }) {
        if (E::stage == which) E::correct(view(E::spec.effect), sig);
      }
    });
  };
  stage(ImuStage::Offset);
  sig.accel = raw.specific_force_b_m_s2 - sig.accel_offset - sig.accel_temp_offset;
  sig.gyro = raw.angular_rate_b_rad_s - sig.gyro_offset - sig.gyro_temp_offset;
  stage(ImuStage::Scale);
  stage(ImuStage::CrossAxis);
  stage(ImuStage::Coupling);
  BodyRates out;
  out.specific_force_b_m_s2 = sig.accel;
  out.angular_rate_b_rad_s = sig.gyro;
  return out;
}

void ErrorStateFilter::set_gps_bias_sigma(const Eigen::Vector3d& fix_sigma_ned_m, double dt_s,
                                          const Eigen::Vector3d& white_scale) {
  constexpr double kMinCorrelatedFraction = 0.01;
  gps_white_fraction_ned_ = (1.0 - tuning_.gps_bias_variance_fraction) * white_scale.cwiseAbs2();
  const Eigen::Vector3d correlated =
      (Eigen::Vector3d::Ones() - gps_white_fraction_ned_).cwiseMax(kMinCorrelatedFraction);
  const Eigen::Vector3d target = correlated.cwiseSqrt().cwiseProduct(fix_sigma_ned_m);
  if (!(dt_s > 0.0)) {  // the first fix: the GM starts in its stationary distribution
    gps_bias_sigma_ned_m_ = target;
    if (layout_.has(Effect::GpsPositionBias)) reset_block(layout_.of(Effect::GpsPositionBias), target);
    return;
  }
  // Later fixes move the GM's level at its own pace (variance averaged over tau).
  const double a = std::min(1.0, dt_s / tuning_.gps_bias_tau_s);
  const Eigen::Vector3d var = gps_bias_sigma_ned_m_.cwiseAbs2() + a * (target.cwiseAbs2() - gps_bias_sigma_ned_m_.cwiseAbs2());
  gps_bias_sigma_ned_m_ = var.cwiseSqrt();
}

void ErrorStateFilter::seed_position_from(const Measurement& m) {
  const Eigen::Index p = layout_.pos.start;
  constexpr double kFloorVariance = 0.01;  // 0.1 m: no fix pins the INS closer than that
  Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxStates> A = m.H.topRows(3);
  A.middleCols(p, 3).setZero();
  Eigen::Matrix3d Ppp = A * P_ * A.transpose() + m.R.topLeftCorner(3, 3);
  // The latency's part (its error times the velocity, along the track) is
  // counted in the position's variance but not tied to the latency state:
  // tied, every later fix of a straight leg, shifted along the track by the
  // receiver's correlated error, moved the latency as if it had seen it
  // (docs/experiments.md, "Starting in the air": 18 air starts of two
  // simulated flights, first 5 min, 1.04 -> 1.36 m tied, 1.14 m counted).
  const Slice latency = layout_.of(Effect::GpsLatency);
  if (latency.active()) A.col(latency.start).setZero();
  const Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxStates> cross = -A * P_;
  for (Eigen::Index i = 0; i < 3; ++i) Ppp(i, i) = std::max(Ppp(i, i), kFloorVariance);
  P_.middleRows(p, 3) = cross;
  P_.middleCols(p, 3) = cross.transpose();
  P_.block(p, p, 3, 3) = 0.5 * (Ppp + Ppp.transpose());
}

void ErrorStateFilter::add_axis_states(Eigen::Index axis, StateMask& mask) const {
  const StateLayout& L = layout_;
  for (Eigen::Index j = 0; j < L.order; ++j) mask.set(static_cast<std::size_t>(L.sensor_state(axis) + j));
  const Triad triad = axis < sensor_axis::kFirstGyro ? Triad::Accel : Triad::Gyro;
  const Eigen::Index i = axis % 3;
  for (const EffectSpec& e : kEffects) {
    if (e.triad != triad || !L.has(e.effect)) continue;
    const Slice& s = L.of(e.effect);
    for (Eigen::Index k = 0; k < s.size; ++k)
      if (effect_component_axis(e.components, k) == i) mask.set(static_cast<std::size_t>(s.start + k));
  }
}

void ErrorStateFilter::rotate_block(const Slice& block, const Eigen::Matrix3d& G) {
  const Eigen::Index b = block.start;
  const StateMat rows = G * P_.middleRows(b, 3);  // 3 x n
  P_.middleRows(b, 3) = rows;
  P_.middleCols(b, 3) = rows.transpose();
  P_.block(b, b, 3, 3) = rows.middleCols(b, 3) * G.transpose();
}

void ErrorStateFilter::add_block_noise(const Slice& block, const Eigen::Matrix3d& Q) {
  if (block.start == layout_.att.start && layout_.has(Effect::MagEarthField)) {
    add_field_coupled_noise(Q, true);
    return;
  }
  P_.block(block.start, block.start, 3, 3) += 0.5 * (Q + Q.transpose());
}

void ErrorStateFilter::add_field_coupled_noise(const Eigen::Matrix3d& Q_att, bool attitude_block_too) {
  const Eigen::Index A = layout_.att.start, M = layout_.of(Effect::MagEarthField).start;
  const Eigen::Matrix3d Q = 0.5 * (Q_att + Q_att.transpose());
  const Eigen::Matrix3d Fx = skew(mag_earth_field_n_uT());
  if (attitude_block_too) P_.block(A, A, 3, 3) += Q;
  P_.block(M, M, 3, 3) += Fx * Q * Fx.transpose();
  P_.block(M, A, 3, 3) += Fx * Q;
  P_.block(A, M, 3, 3) += Q * Fx.transpose();
}

void ErrorStateFilter::reset_block(const Slice& block, const Eigen::Vector3d& sigma) {
  for (Eigen::Index i = 0; i < 3; ++i) reset_state(block.start + i, sigma(i));
}

void ErrorStateFilter::reset_state(Eigen::Index i, double sigma) {
  P_.row(i).setZero();
  P_.col(i).setZero();
  P_(i, i) = sigma * sigma;
}

void ErrorStateFilter::reset_yaw(NavState& nav, double dyaw_rad, double sigma_rad) {
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(dyaw_rad, Eigen::Vector3d::UnitZ()));
  nav.q_nb = (turn * nav.q_nb).normalized();
  // The field turns with the solution: the invariant field error (state_layout.hpp) is unchanged.
  const Eigen::Vector3d F_n = turn * mag_earth_field_n_uT();
  for (Eigen::Index i = 0; i < 3; ++i) set_effect(Effect::MagEarthField, i, F_n(i));
  if (layout_.has(Effect::MagEarthField)) rotate_block(layout_.of(Effect::MagEarthField), turn.toRotationMatrix());
  const Eigen::Index d = layout_.att.start + 2;
  P_.row(d).setZero();
  P_.col(d).setZero();
  P_(d, d) = sigma_rad * sigma_rad;
}

void ErrorStateFilter::seed_attitude(const Eigen::Vector3d& att_sigma_rad) {
  reset_block(layout_.att, att_sigma_rad);
}

BodyRates ErrorStateFilter::compensate_at_rest(const Eigen::Vector3d& f_b) const {
  ImuSample rest;
  rest.specific_force_b_m_s2 = f_b;
  rest.temp_degC = temp_ref_degC_;
  rest.has_temp = true;
  return compensate(rest);
}

MeasJacobian ErrorStateFilter::rest_rows(const NavState& nav, const Eigen::Vector3d& f_b, Eigen::Index rows,
                                         bool with_tilt) const {
  const Eigen::Index n = layout_.dim;
  // The body columns through the attitude now (as the tilt error is carried
  // on): measured on the real drive, the window's own attitude, which a car
  // has turned away from by the time the course aligns it, kept the heading
  // from converging without GNSS velocity (GGA only: 9.9 against 3.0 m of
  // outage drift). The levelled specific force is vertical by construction.
  PredictInput in;
  in.nav = &nav;
  in.specific_force_b_m_s2 = f_b;
  in.angular_rate_b_rad_s = Eigen::Vector3d::Zero();
  in.specific_force_n_m_s2 = Eigen::Vector3d(0.0, 0.0, -f_b.norm());
  in.dt_s = 1.0;  // Phi - I is then the error dynamics' rate matrix
  StateMat Phi(n, n);
  StateVec q(n);
  build_transition(in, 0, Phi, q);
  MeasJacobian H = Phi.block(rows, 0, 3, n);
  // The navigation states: only the tilt (with_tilt) is in the
  // rest's statement; Coriolis, the gravity gradient and Earth rate are nothing at rest.
  const Eigen::Matrix<double, 3, 2> tilt = H.block(0, layout_.att.start, 3, 2);
  for (const Slice& nav_block : {layout_.pos, layout_.vel, layout_.att}) H.middleCols(nav_block.start, 3).setZero();
  if (with_tilt) H.block(0, layout_.att.start, 3, 2) = tilt;
  // The coloured error's states are the error of this instant, not of the
  // window's mean: its variance is noise on the mean.
  H.middleCols(layout_.sensor.start, layout_.sensor.size).setZero();
  return H;
}

double ErrorStateFilter::coloured_variance(Eigen::Index first_axis) const {
  double v = 0.0;
  for (Eigen::Index i = 0; i < 3; ++i) {
    const Eigen::Index c = layout_.sensor_state(first_axis + i);
    v = std::max(v, P_(c, c));
  }
  return v;
}

void ErrorStateFilter::correlate_gyro_bias_at_rest(const NavState& nav, const Eigen::Vector3d& f_b) {
  if (!layout_.has(Effect::GyroBias)) return;
  // seed_gyro_bias gave the rest's mean rate to the bias, with the mean's
  // noise. But that mean is the sum of what enters the gyro at rest: the
  // bias and, at this f, a g-sensitivity's column along gravity. As for the
  // levelling: the bias free, the statement fused with zero innovation (the
  // value is already the bias's), so the bias's error carries the others'
  // (d b = -G_z d f_z): a g-sensitivity the rest hid in the bias is then
  // learnt from the load factor's changes instead of held at zero by level
  // flight.
  const Eigen::Index B = layout_.of(Effect::GyroBias).start, n = layout_.dim;
  Eigen::Vector3d seeded;
  for (Eigen::Index i = 0; i < 3; ++i) seeded(i) = P_(B + i, B + i);
  constexpr double kFreeBias_rad_s = 1.0;
  for (Eigen::Index i = 0; i < 3; ++i) reset_state(B + i, kFreeBias_rad_s);
  Measurement m;
  m.gate_sigma = 1e9;
  m.innovation = Eigen::Vector3d::Zero();
  m.H = rest_rows(nav, compensate_at_rest(f_b).specific_force_b_m_s2, layout_.att.start, false);
  m.R = MeasMat::Zero(3, 3);
  // Per navigation axis: the seeded variance of the body axes it sees (level at rest).
  const Eigen::Matrix3d C = nav.C_nb();
  m.R.topLeftCorner(3, 3) = C * seeded.asDiagonal() * C.transpose();
  StateVec dx(n);
  fuse_measurement(P_, dx, m);
}

void ErrorStateFilter::seed_accel_bias_at_rest(NavState& nav, const Eigen::Vector3d& f_b, double sigma_along) {
  if (!(f_b.norm() > 0.0)) return;
  const Eigen::Index n = layout_.dim, V = layout_.vel.start, A = layout_.att.start;
  // The levelling said "C_nb f + g_n = 0" of the rest window's mean f and set
  // the tilt from it. Fused as the measurement it is, against a free tilt:
  // every state that enters that mean (the bias, a misalignment's or a
  // scale's columns at this f: the velocity rows of the error dynamics, as
  // each effect file writes them) shares its error with the tilt. (A tilt
  // correlated with the bias alone let a cross-axis term such as xz, which
  // the levelling had put into the pitch just as much, "learn" 20 mrad at rest
  // and then hold a wrong value for the flight.)
  const Eigen::Matrix2d tilt_noise = P_.block(A, A, 2, 2);  // seed_attitude's: the levelling's noise, the gyro carry
  constexpr double kFreeTilt_rad = 1.0;
  for (Eigen::Index i = 0; i < 2; ++i) reset_state(A + i, kFreeTilt_rad);
  // Along gravity the rest measures the bias, as it always did: its value
  // there is |f| - g (of the mean compensated with the other estimates) and
  // its variance the mean's noise and the coloured error's. (Shared with a z
  // scale by the same statement, the pair drifted along its ridge on the
  // real drive, which never changes f_z: z scale 14 %, bias 1.3 m/s^2.)
  // Its variance also holds what the other states put along gravity (a z
  // scale's g s_z), uncorrelated with them: the rest cannot tell them apart,
  // and a bias as sure as the mean's noise alone would make the flight
  // "measure" a z scale from it that level flight cannot see (a hovering
  // quadcopter's 1 % z scale came out 0.04 +- 0.13 %).
  const BodyRates comp = compensate_at_rest(f_b);
  if (layout_.has(Effect::AccelBias)) {
    const Eigen::Index B = layout_.of(Effect::AccelBias).start;
    const Eigen::Vector3d u = f_b.normalized();  // "up" in the body frame
    const Eigen::Vector3d b = accel_bias_measured_at_rest(nav, f_b);
    for (Eigen::Index i = 0; i < 3; ++i) set_effect(Effect::AccelBias, i, b(i));
    MeasJacobian along = rest_rows(nav, comp.specific_force_b_m_s2, V, false).row(2);  // the vertical's rate
    along.middleCols(B, 3).setZero();
    const double others = (along * P_ * along.transpose())(0, 0);
    const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - u * u.transpose();
    const Eigen::Matrix3d Pb =
        across * P_.block(B, B, 3, 3) * across +
        (sigma_along * sigma_along + coloured_variance(sensor_axis::kFirstAccel) + others) * u * u.transpose();
    for (Eigen::Index i = 0; i < 3; ++i) reset_state(B + i, 0.0);
    P_.block(B, B, 3, 3) = Pb;
  }
  // Across gravity: the levelling made the horizontal part exact, so the tilt
  // error is minus the horizontal sum of every state's share over g.
  Measurement m;
  m.gate_sigma = 1e9;  // the levelling's own statement: never rejected
  m.innovation = Eigen::Vector2d::Zero();
  m.H = rest_rows(nav, comp.specific_force_b_m_s2, V, true).topRows(2);
  constexpr double kExact_m_s2 = 1e-6;  // its noise is the tilt's, added back below
  m.R = MeasMat::Identity(2, 2) * (kExact_m_s2 * kExact_m_s2);
  StateVec dx(n);
  if (fuse_measurement(P_, dx, m).accepted) feedback(dx, nav);
  P_.block(A, A, 2, 2) += tilt_noise;
}

Eigen::Vector3d ErrorStateFilter::accel_bias_measured_at_rest(const NavState& nav, const Eigen::Vector3d& f_b) const {
  const double f_norm = compensate_at_rest(f_b).specific_force_b_m_s2.norm();
  const double g = wgs84::normal_gravity_m_s2(nav.lat_rad, nav.h_m);
  return view(Effect::AccelBias).vec3() + f_b.normalized() * (f_norm - g);
}

double ErrorStateFilter::accel_bias_along_gravity_at_rest(const NavState& nav, const Eigen::Vector3d& f_b) const {
  if (!layout_.has(Effect::AccelBias) || !(f_b.norm() > 0.0)) return NAN;
  return f_b.normalized().dot(accel_bias_measured_at_rest(nav, f_b));
}

double ErrorStateFilter::sensor_error(Eigen::Index axis) const { return sensor_hat_(hat_index(axis)); }

void ErrorStateFilter::seed_gyro_bias(const Eigen::Vector3d& mean_rate_b, const Eigen::Vector3d& f_b, double sigma) {
  // The bias is what compensate() must take off the mean rate to leave no
  // rate; it is affine in the bias with a gain near -I (a scale's or a
  // misalignment's 1e-3 beside it), so a step or two settle it. Counted twice,
  // a model file's g-sensitivity of 5e-4 rad/s per m/s^2 turned the heading
  // 12 deg in the first 48 s (docs/diagnose.md).
  ImuSample rest;
  rest.specific_force_b_m_s2 = f_b;
  rest.angular_rate_b_rad_s = mean_rate_b;
  rest.temp_degC = temp_ref_degC_;
  rest.has_temp = true;
  Eigen::Vector3d bias = mean_rate_b;
  for (int step = 0; step < 3; ++step) {
    put_gyro_bias(bias, sigma);
    const Eigen::Vector3d left = compensate(rest).angular_rate_b_rad_s;
    if (!(left.squaredNorm() > 0.0)) return;
    bias += left;
  }
  put_gyro_bias(bias, sigma);
}

void ErrorStateFilter::put_gyro_bias(const Eigen::Vector3d& bias, double sigma) {
  if (layout_.has(Effect::GyroBias)) {
    for (Eigen::Index i = 0; i < 3; ++i) set_effect(Effect::GyroBias, i, bias(i));
    const Eigen::Index s = layout_.of(Effect::GyroBias).start;
    for (Eigen::Index i = 0; i < 3; ++i) {
      // The window's mean also holds the coloured error of that moment, which
      // the sensor states model as zero-mean: count its variance too.
      const Eigen::Index c = layout_.sensor_state(sensor_axis::kFirstGyro + i);
      P_(s + i, s + i) = std::min(P_(s + i, s + i), sigma * sigma + P_(c, c));
    }
    return;
  }
  const Eigen::Index p = layout_.order;
  for (Eigen::Index i = 0; i < 3; ++i) {
    const Eigen::Index axis = sensor_axis::kFirstGyro + i;
    sensor_hat_.segment(hat_index(axis), p).setConstant(bias(i));
    const Eigen::Index s = layout_.sensor_state(axis);
    // Keep the block's correlation structure, shrink it to the measured uncertainty.
    const double scale = P_(s, s) > 0.0 ? std::min(1.0, sigma * sigma / P_(s, s)) : 0.0;
    P_.block(s, 0, p, P_.cols()) *= std::sqrt(scale);
    P_.block(0, s, P_.rows(), p) *= std::sqrt(scale);
  }
}

double ErrorStateFilter::sensor_error_sigma(Eigen::Index axis) const {
  const Eigen::Index s = layout_.sensor_state(axis);
  return std::sqrt(P_(s, s));
}

double ErrorStateFilter::effect(Effect e, Eigen::Index i) const { return view(e).v[i]; }

void ErrorStateFilter::set_effect(Effect e, Eigen::Index i, double v) { values(e)[i] = v; }

void ErrorStateFilter::apply_priors() {
  for (std::size_t e = 0; e < kEffectCount; ++e) apply_prior(static_cast<Effect>(e));
}

void ErrorStateFilter::set_prior(Effect e, const EffectPrior& prior) {
  tuning_.prior[static_cast<std::size_t>(e)] = prior;
  apply_prior(e);
}

void ErrorStateFilter::apply_prior(Effect e) {
  const EffectPrior& p = tuning_.prior[static_cast<std::size_t>(e)];
  if (!p.given || !layout_.has(e)) return;
  const Slice& s = layout_.of(e);
  for (Eigen::Index i = 0; i < s.size; ++i) {
    const auto k = static_cast<std::size_t>(i);
    set_effect(e, i, p.value[k]);
    P_.row(s.start + i).setZero();
    P_.col(s.start + i).setZero();
    P_(s.start + i, s.start + i) = p.sigma[k] * p.sigma[k];
  }
}

double ErrorStateFilter::effect_sigma(Effect e, Eigen::Index i) const {
  if (!layout_.has(e)) return 0.0;
  const Eigen::Index s = layout_.of(e).start + i;
  return std::sqrt(P_(s, s));
}

}  // namespace sinu::est
