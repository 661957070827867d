#include "estimator/ekf/error_state_filter.hpp"

#include <algorithm>
#include <cmath>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ekf/covariance.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

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
  gps_bias_ned_.setZero();
  mag_field_n_.setZero();
  mag_hard_iron_b_.setZero();
  mag_soft_iron_.setZero();
  sensor_hat_ = StateVec::Zero(layout.sensor.size);
  ar_clock_s_ = 0.0;
}

void ErrorStateFilter::reanchor_hard_iron(const NavState& nav, const Eigen::Vector3d& mag_b_uT, double sigma_uT) {
  if (!layout_.has(Effect::MagHardIron)) return;
  const Eigen::Vector3d predicted = mag_soft_iron() * (nav.C_nb().transpose() * mag_field_n_);
  mag_hard_iron_b_ = mag_b_uT - predicted;
  const Slice& H = layout_.of(Effect::MagHardIron);
  const double keep = std::sqrt(P_.block(H.start, H.start, 3, 3).diagonal().maxCoeff());
  reset_block(H, Eigen::Vector3d::Constant(std::hypot(sigma_uT, keep)));
}

void ErrorStateFilter::activate_deferred() {
  if (!layout_.has_deferred()) return;
  const Eigen::Index n = layout_.dim;
  const StateLayout before = layout_;
  layout_.activate_deferred();
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
  auto couple = [&](Effect e, Eigen::Index row, double sign, const Eigen::Vector3d& scale) {
    if (!L.has(e)) return;
    Phi.block(row, L.of(e).start, 3, 3) += sign * C * scale.asDiagonal() * dt;
  };
  couple(Effect::AccelScale, V, 1.0, in.specific_force_b_m_s2);
  couple(Effect::GyroScale, A, -1.0, in.angular_rate_b_rad_s);
  couple(Effect::AccelBias, V, 1.0, Eigen::Vector3d::Ones());
  couple(Effect::GyroBias, A, -1.0, Eigen::Vector3d::Ones());
  couple(Effect::AccelTempBias, V, 1.0, Eigen::Vector3d::Constant(in.temp_delta_degC));
  couple(Effect::GyroTempBias, A, -1.0, Eigen::Vector3d::Constant(in.temp_delta_degC));
  // Misalignment (i, j): axis i senses axis j, so its error moves sensor axis i
  // by the other axis's reading; g-sensitivity (i, j): gyro i by specific force j.
  if (L.has(Effect::AccelMisalign)) {
    for (Eigen::Index k = 0; k < 6; ++k) {
      const auto [i, j] = kOffDiagonal[static_cast<std::size_t>(k)];
      Phi.block(V, L.of(Effect::AccelMisalign).start + k, 3, 1) += C.col(i) * (in.specific_force_b_m_s2(j) * dt);
    }
  }
  if (L.has(Effect::GyroMisalign)) {
    for (Eigen::Index k = 0; k < 6; ++k) {
      const auto [i, j] = kOffDiagonal[static_cast<std::size_t>(k)];
      Phi.block(A, L.of(Effect::GyroMisalign).start + k, 3, 1) -= C.col(i) * (in.angular_rate_b_rad_s(j) * dt);
    }
  }
  if (L.has(Effect::GyroGSensitivity)) {
    for (Eigen::Index i = 0; i < 3; ++i)
      for (Eigen::Index j = 0; j < 3; ++j)
        Phi.block(A, L.of(Effect::GyroGSensitivity).start + 3 * i + j, 3, 1) -=
            C.col(i) * (in.specific_force_b_m_s2(j) * dt);
  }
  if (L.has(Effect::MagEarthField)) {  // e = dF + [F x] phi moves with phi: e_k+1 = e_k + [F x] (phi_k+1 - phi_k)
    const Eigen::Index M = L.of(Effect::MagEarthField).start;
    Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxStates> dphi = Phi.middleRows(A, 3);
    dphi.middleCols(A, 3) -= Eigen::Matrix3d::Identity();
    Phi.middleRows(M, 3) += skew(mag_field_n_) * dphi;
  }

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
  auto bias_walk = [&](Effect e, double walk) {
    if (!L.has(e) || !(walk > 0.0)) return;
    q.segment(L.of(e).start, 3).setConstant(walk * walk * dt);
  };
  bias_walk(Effect::AccelBias, noise_.accel_bias_walk);
  bias_walk(Effect::GyroBias, noise_.gyro_bias_walk);
  if (L.has(Effect::GpsPositionBias)) {  // first-order GM per NED axis
    const Eigen::Index b = L.of(Effect::GpsPositionBias).start;
    const double phi = std::exp(-dt / tuning_.gps_bias_tau_s);
    for (Eigen::Index j = 0; j < 3; ++j) {
      Phi(b + j, b + j) = phi;
      q(b + j) = gps_bias_sigma_ned_m_(j) * gps_bias_sigma_ned_m_(j) * (1.0 - phi * phi);
    }
  }
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
  if (layout_.has(Effect::GpsPositionBias)) gps_bias_ned_ *= std::exp(-in.dt_s / tuning_.gps_bias_tau_s);
}

Eigen::Matrix3d ErrorStateFilter::mag_soft_iron() const {
  const auto& d = mag_soft_iron_;
  Eigen::Matrix3d S;
  S << 1.0 + d(0), d(3), d(4), d(3), 1.0 + d(1), d(5), d(4), d(5), 1.0 + d(2);
  return S;
}

void ErrorStateFilter::start_mag_field(const NavState& nav, const Eigen::Vector3d& mag_b_uT, double noise_sigma_uT) {
  const Eigen::Matrix3d C = nav.C_nb();
  mag_field_n_ = C * mag_soft_iron().inverse() * (mag_b_uT - mag_hard_iron_b_);
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
  const double rm = wgs84::meridian_radius_m(nav.lat_rad) + nav.h_m;
  const double rn = wgs84::transverse_radius_m(nav.lat_rad) + nav.h_m;
  const Eigen::Vector3d dp = dx.segment(L.pos.start, 3);
  nav.lat_rad -= dp.x() / rm;
  nav.lon_rad -= dp.y() / (rn * std::cos(nav.lat_rad));
  nav.h_m += dp.z();
  nav.v_n_m_s -= dx.segment(L.vel.start, 3);
  nav.q_nb = (quat_from_rotation_vector(dx.segment(L.att.start, 3)) * nav.q_nb).normalized();
  sensor_hat_ += dx.segment(L.sensor.start, L.sensor.size);
  for (std::size_t k = 0; k < kEffectCount; ++k) {
    const auto e = static_cast<Effect>(k);
    if (!L.has(e) || e == Effect::MagEarthField) continue;
    for (Eigen::Index i = 0; i < L.of(e).size; ++i) effect_slot(*this, e, i) += dx(L.of(e).start + i);
  }
  if (L.has(Effect::MagEarthField)) {
    // e = dF + [F x] phi: the field turns with the attitude correction (exactly,
    // as the attitude does), and so does its error, a navigation-frame vector
    // (the reset Jacobian: without it a large heading correction leaves the
    // field's covariance pointing the old way and the next turns diverge).
    const Eigen::Vector3d phi = dx.segment(L.att.start, 3);
    const Eigen::Matrix3d R = quat_from_rotation_vector(phi).toRotationMatrix();
    mag_field_n_ = R * mag_field_n_ + dx.segment(L.of(Effect::MagEarthField).start, 3);
    rotate_block(L.of(Effect::MagEarthField), R);
  }
  dx.setZero();
}

BodyRates ErrorStateFilter::compensate(const ImuSample& raw) const {
  const double dT = raw.has_temp ? raw.temp_degC - temp_ref_degC_ : 0.0;
  Eigen::Vector3d ba, bg;
  for (Eigen::Index i = 0; i < 3; ++i) {
    ba(i) = sensor_hat_(hat_index(sensor_axis::kFirstAccel + i)) + accel_bias_(i);
    bg(i) = sensor_hat_(hat_index(sensor_axis::kFirstGyro + i)) + gyro_bias_(i);
  }
  BodyRates out;
  const Eigen::Vector3d f =
      (Eigen::Vector3d::Ones() - accel_scale_).cwiseProduct(raw.specific_force_b_m_s2 - ba - accel_temp_ * dT);
  const Eigen::Vector3d w =
      (Eigen::Vector3d::Ones() - gyro_scale_).cwiseProduct(raw.angular_rate_b_rad_s - bg - gyro_temp_ * dT);
  out.specific_force_b_m_s2 = f - accel_misalign_ * f;
  out.angular_rate_b_rad_s = w - gyro_misalign_ * w - gyro_g_ * out.specific_force_b_m_s2;
  return out;
}

void ErrorStateFilter::set_gps_bias_sigma(const Eigen::Vector3d& fix_sigma_ned_m, double dt_s) {
  const Eigen::Vector3d target = std::sqrt(tuning_.gps_bias_variance_fraction) * fix_sigma_ned_m;
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

void ErrorStateFilter::seed_position_from_fix(const Eigen::Vector3d& fix_sigma_ned_m) {
  reset_block(layout_.pos, fix_sigma_ned_m.cwiseMax(0.1));
  if (!layout_.has(Effect::GpsPositionBias)) return;
  // p_hat = p + b + w: dp = b + w; the bias state's error is b (true - estimated, b_hat = 0).
  const Eigen::Index p = layout_.pos.start, b = layout_.of(Effect::GpsPositionBias).start;
  const Eigen::Matrix3d Pbb = P_.block(b, b, 3, 3);
  P_.block(p, b, 3, 3) = Pbb;
  P_.block(b, p, 3, 3) = Pbb;
}

void ErrorStateFilter::add_axis_states(Eigen::Index axis, StateMask& mask) const {
  const StateLayout& L = layout_;
  for (Eigen::Index j = 0; j < L.order; ++j) mask.set(static_cast<std::size_t>(L.sensor_state(axis) + j));
  const bool accel = axis < sensor_axis::kFirstGyro;
  const Eigen::Index i = axis % 3;
  for (const Effect e : accel ? std::array{Effect::AccelBias, Effect::AccelScale, Effect::AccelTempBias}
                              : std::array{Effect::GyroBias, Effect::GyroScale, Effect::GyroTempBias}) {
    if (L.has(e)) mask.set(static_cast<std::size_t>(L.of(e).start + i));
  }
  // The axis's row of its misalignment (and of the g-sensitivity for a gyro).
  const Effect misalign = accel ? Effect::AccelMisalign : Effect::GyroMisalign;
  if (L.has(misalign)) {
    for (Eigen::Index k = 0; k < 6; ++k)
      if (kOffDiagonal[static_cast<std::size_t>(k)][0] == i) mask.set(static_cast<std::size_t>(L.of(misalign).start + k));
  }
  if (!accel && L.has(Effect::GyroGSensitivity)) {
    for (Eigen::Index j = 0; j < 3; ++j) mask.set(static_cast<std::size_t>(L.of(Effect::GyroGSensitivity).start + 3 * i + j));
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
  const Eigen::Matrix3d Fx = skew(mag_field_n_);
  if (attitude_block_too) P_.block(A, A, 3, 3) += Q;
  P_.block(M, M, 3, 3) += Fx * Q * Fx.transpose();
  P_.block(M, A, 3, 3) += Fx * Q;
  P_.block(A, M, 3, 3) += Q * Fx.transpose();
}

void ErrorStateFilter::reset_block(const Slice& block, const Eigen::Vector3d& sigma) {
  P_.middleRows(block.start, 3).setZero();
  P_.middleCols(block.start, 3).setZero();
  for (Eigen::Index i = 0; i < 3; ++i) P_(block.start + i, block.start + i) = sigma(i) * sigma(i);
}

void ErrorStateFilter::reset_yaw(NavState& nav, double dyaw_rad, double sigma_rad) {
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(dyaw_rad, Eigen::Vector3d::UnitZ()));
  nav.q_nb = (turn * nav.q_nb).normalized();
  // The field turns with the solution: the invariant field error (state_layout.hpp) is unchanged.
  mag_field_n_ = turn * mag_field_n_;
  if (layout_.has(Effect::MagEarthField)) rotate_block(layout_.of(Effect::MagEarthField), turn.toRotationMatrix());
  const Eigen::Index d = layout_.att.start + 2;
  P_.row(d).setZero();
  P_.col(d).setZero();
  P_(d, d) = sigma_rad * sigma_rad;
}

void ErrorStateFilter::seed_attitude(const Eigen::Vector3d& att_sigma_rad) {
  reset_block(layout_.att, att_sigma_rad);
}

void ErrorStateFilter::seed_accel_bias_at_rest(const NavState& nav, const Eigen::Vector3d& f_b, double g,
                                               double sigma_along) {
  if (!layout_.has(Effect::AccelBias) || !(f_b.norm() > 0.0)) return;
  const Slice& B = layout_.of(Effect::AccelBias);
  const Eigen::Vector3d u = f_b.normalized();  // "up" in the body frame
  // The along-gravity part is measured; the rest keeps its prior.
  accel_bias_ = accel_bias_ - u * u.dot(accel_bias_) + u * (f_b.norm() - g);
  const Eigen::Matrix3d Pb_prior = P_.block(B.start, B.start, 3, 3);
  const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - u * u.transpose();
  double coloured = 0.0;  // the coloured error at rest is in the mean too (as for the gyro)
  for (Eigen::Index i = 0; i < 3; ++i) {
    const Eigen::Index c = layout_.sensor_state(sensor_axis::kFirstAccel + i);
    coloured = std::max(coloured, P_(c, c));
  }
  const Eigen::Matrix3d Pb =
      across * Pb_prior * across + (sigma_along * sigma_along + coloured) * u * u.transpose();
  // Tilt error made by the levelling from the horizontal bias error.
  const Eigen::Matrix3d C = nav.C_nb();
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  M.row(0) = C.row(1) / g;
  M.row(1) = -C.row(0) / g;
  const Slice& A = layout_.att;
  const Eigen::Matrix3d Paa_before = P_.block(A.start, A.start, 3, 3);  // seed_attitude's: noise, gyro carry, yaw
  reset_block(B, Eigen::Vector3d::Zero());
  P_.block(B.start, B.start, 3, 3) = Pb;
  reset_block(A, Eigen::Vector3d::Zero());
  P_.block(A.start, A.start, 3, 3) = Paa_before + M * Pb * M.transpose();
  P_.block(A.start, B.start, 3, 3) = M * Pb;
  P_.block(B.start, A.start, 3, 3) = (M * Pb).transpose();
}

double ErrorStateFilter::sensor_error(Eigen::Index axis) const { return sensor_hat_(hat_index(axis)); }

void ErrorStateFilter::seed_gyro_bias(const Eigen::Vector3d& bias, double sigma) {
  if (layout_.has(Effect::GyroBias)) {
    gyro_bias_ = bias;
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

double ErrorStateFilter::effect(Effect e, Eigen::Index i) const { return effect_slot(*this, e, i); }

void ErrorStateFilter::set_effect(Effect e, Eigen::Index i, double v) { effect_slot(*this, e, i) = v; }

void ErrorStateFilter::apply_priors() {
  for (std::size_t e = 0; e < kEffectCount; ++e) apply_prior(static_cast<Effect>(e));
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
