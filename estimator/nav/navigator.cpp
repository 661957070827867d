// The navigator's core: the IMU stream screened, prefiltered and propagated,
// the alignment, the generic update and the health flags. The aiding sources
// and the restart are in navigator_*.cpp, one file each (as PX4 EKF2 keeps
// one file per aiding source of its Ekf class).
#include "estimator/nav/navigator.hpp"

#include <algorithm>
#include <cmath>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

namespace {

/// The layout the configuration asks for: the magnetometer's states reserved
/// (deferred) when it is to be used, dropped when not.
StateLayout layout_of(const NavigatorConfig& cfg) {
  EffectSet effects = cfg.effects, deferred;
  if (cfg.use_mag) {
    effects.add(Effect::MagEarthField);  // the 3-axis model needs both (PX4 EKF2 likewise)
    effects.add(Effect::MagHardIron);
    for (const Effect e : kMagEffects)
      if (effects.has(e)) deferred.add(e);
  } else {
    for (const Effect e : kMagEffects) effects.remove(e);
  }
  if (cfg.vehicle == VehicleKind::Auto) {  // a unit on a bracket: its yaw there (vehicle_detector.hpp)
    effects.add(Effect::VehicleMount);
    deferred.add(Effect::VehicleMount);
  }
  return StateLayout::make(cfg.noise.order(), effects, deferred);
}

}  // namespace

void Navigator::init(const NavigatorConfig& cfg, NavObserver* observer, ImuPrefilter* prefilter) {
  cfg_ = cfg;
  observer_ = observer;
  prefilter_ = prefilter ? prefilter : &pass_through_;
  imu_.clear();
  gnss_.clear();
  screen_.configure(cfg.screen);
  alignment_.configure(cfg.alignment);
  scale_check_.configure(cfg.scale_check);
  alignment_result_ = {};
  recovery_.configure(cfg.recovery);
  vertical_.configure(cfg.vertical);
  heading_.configure(cfg.heading);
  course_hold_.configure(cfg.course_hold);
  vel_noise_started_ = false;
  stillness_.configure(cfg.stillness);
  vehicle_.configure(cfg.vehicle_detector);
  still_now_ = false;
  last_gnss_speed_m_s_ = 1e9;
  last_zupt_t_s_ = last_nhc_t_s_ = 0.0;
  mag_noise_.configure(cfg.mag_noise, cfg.mag_sigma_uT);
  pos_scale_h_.configure(cfg.gnss_position_scale, 1.0);
  pos_scale_v_.configure(cfg.gnss_position_scale, 1.0);
  white_h_.configure(white_scale_config(), 1.0);
  white_v_.configure(white_scale_config(), 1.0);
  last_pos_scale_t_s_ = last_stated_t_s_ = kNever;
  course_t_s_ = heading_yaw_t_s_ = course_contradicted_since_s_ = kNever;
  course_rate_rad_s_ = yaw_rate_rad_s_ = 0.0;
  mag_reject_since_s_ = -1.0;
  have_prev_ = have_raw_ = mag_started_ = in_timeout_ = false;
  last_gap_t_s_ = disturbed_t_s_ = -1e300;
  horizon_now_s_ = cfg.horizon_s;
  raw_period_.reset();
  period_.reset();
  horizontal_accel_m_s2_ = accel_diff_var_ = gyro_diff_var_ = 0.0;
  clip_until_t_s_.fill(kNever);
  last_clip_t_s_.fill(kNever);
  clip_run_.fill(0);
  frozen_.reset();
  events_ = state_flags_ = 0;
  test_ratio_.fill(0.0);
  predict_.clear();
  counters_ = {};
  nav_ = {};
  warm_ = {};
  filter_.init(layout_of(cfg), cfg.noise, cfg.tuning, cfg.initial);
  filter_.set_lever_arm(cfg.lever_arm_b_m);
  filter_.set_gps_latency(cfg.gps_latency_s);
  filter_.apply_priors();
  dx_ = StateVec::Zero(filter_.layout().dim);
}

void Navigator::push_imu(const ImuSample& raw) {
  // Screened before the prefilter: one NaN would poison a wavelet's registers.
  ImuSample s = raw;
  s.t_s -= cfg_.imu_latency_s;
  switch (screen_.screen(s, s.clipped_axes)) {
    case ScreenVerdict::NonFinite:
      ++counters_.imu_invalid;
      events_ |= nav_flag::kImuDropped;
      return;
    case ScreenVerdict::NotIncreasing:
      ++counters_.imu_non_increasing;
      events_ |= nav_flag::kImuDropped;
      return;
    case ScreenVerdict::Keep: break;
  }
  if (have_raw_) raw_period_.add(raw.t_s - last_raw_t_s_);  // nominal raw period: gaps and repeats do not move it
  have_raw_ = true;
  last_raw_t_s_ = raw.t_s;
  if (s.clipped_axes) {
    ++counters_.imu_clipped_samples;
    // A clipped input reaches every prefilter output up to its delay later.
    const double reach = s.t_s + prefilter_->delay_samples() * raw_period_.seconds() + 1e-9;
    for (std::size_t a = 0; a < kSensorAxes; ++a)
      if ((static_cast<unsigned>(s.clipped_axes) >> a) & 1u) clip_until_t_s_[a] = reach;
  }
  ImuSample out;
  if (prefilter_->push(s, out)) push_filtered(out);
}

void Navigator::push_filtered(ImuSample s) {
  for (std::size_t a = 0; a < kSensorAxes; ++a)
    if (s.t_s <= clip_until_t_s_[a]) s.clip_reach_axes |= static_cast<std::uint8_t>(1u << a);
  if (!imu_.empty() && !(s.t_s > imu_.back().t_s)) {
    ++counters_.imu_non_increasing;
    events_ |= nav_flag::kImuDropped;
    return;
  }
  if (imu_.full()) {  // horizon longer than the buffer: process the oldest now
    process(imu_.front());
    imu_.pop();
  }
  imu_.push(s);
  // Grow the horizon with the latency estimate: samples wait that much longer.
  horizon_now_s_ = std::min(horizon_limit_s(),
                            std::max({horizon_now_s_, cfg_.horizon_s, filter_.gps_latency_s() + cfg_.horizon_margin_s}));
  while (!imu_.empty() && imu_.front().t_s <= s.t_s - horizon_now_s_) {
    process(imu_.front());
    imu_.pop();
  }
}

void Navigator::push_gnss(const GnssObservation& z) {
  GnssObservation in = z;
  if (in.has_velocity && !in.velocity_from_positions && course_hold_.held(in.v_ne_m_s)) {
    in.course_held = true;  // a speed, not a velocity: never fused as one (course_hold.hpp)
    ++counters_.course_held;
  }
  if (!gnss_.push(in)) ++counters_.gnss_overflow;
}

void Navigator::flush() {
  ImuSample s;
  while (prefilter_->drain(s)) push_filtered(s);
  while (!imu_.empty()) {
    process(imu_.front());
    imu_.pop();
  }
}

void Navigator::process(const ImuSample& s) {
  if (!have_prev_) {
    prev_ = s;
    have_prev_ = true;
    return;
  }
  const double dt = s.t_s - prev_.t_s;
  period_.add(dt);
  if (dt > cfg_.gap_periods * period_.seconds()) {
    ++counters_.imu_gaps;
    counters_.imu_gap_total_s += dt;
    counters_.imu_longest_gap_s = std::max(counters_.imu_longest_gap_s, dt);
    events_ |= nav_flag::kImuGap;
  }
  if (!aligned()) {
    align(s, dt);
    prev_ = s;
    if (aligned()) {
      update_health(s.t_s, 0.0);  // the aligned row's state bits (constraints, clipping) are this sample's
      emit();
    }
    return;
  }

  alignment_.add_imu(s, dt);  // after a course alignment, its check (check_course)
  const bool gap = dt > cfg_.gap_periods * period_.seconds();
  if (gap) last_gap_t_s_ = s.t_s;
  const BodyRates r0 = filter_.compensate(prev_);
  const BodyRates r1 = filter_.compensate(s);
  // Across a gap the last sample before it is held: a straight line to the
  // first sample after it would spread that one sample's noise or transient
  // over the whole gap (a real log: one -3.7 m/s^2 sample after a 2-s gap
  // made 5 m/s of vertical velocity). The unknown motion is noise (widen_for_imu_errors).
  const BodyRates& r_end = gap ? r0 : r1;
  Eigen::Vector3d f_n;
  const Eigen::Vector3d v_before = nav_.v_n_m_s;
  strapdown_step(nav_, r0, r_end, dt, f_n);
  nav_.t_s = s.t_s;
  // The acceleration the GNSS velocity update needs (to take the state back to
  // its time of validity, and as the latency's Jacobian), smoothed over
  // ~0.2 s: one sample's velocity step carries the IMU's vibration, which the
  // same update's innovation also carries, and the correlated pair drags the
  // latency estimate (a car on a rough road: -0.09 s for +0.05 s). A gap's
  // mean says nothing of the acceleration at its end.
  if (!gap) accel_n_ += std::min(1.0, dt / 0.2) * ((nav_.v_n_m_s - v_before) / dt - accel_n_);
  if (gap) {
    velocity_history_.clear();
  } else {
    velocity_history_.add(nav_.t_s, nav_.v_n_m_s - v_before);
  }

  PredictInput in;
  in.nav = &nav_;
  in.specific_force_b_m_s2 = 0.5 * (r0.specific_force_b_m_s2 + r_end.specific_force_b_m_s2);
  in.angular_rate_b_rad_s = 0.5 * (r0.angular_rate_b_rad_s + r_end.angular_rate_b_rad_s);
  in.specific_force_n_m_s2 = f_n;
  in.temp_delta_degC = s.has_temp ? s.temp_degC - filter_.reference_temperature() : 0.0;
  in.dt_s = dt;
  if (cfg_.vibration_noise && !gap) {
    const double a = std::min(1.0, dt / cfg_.vibration_tau_s);
    accel_diff_var_ += a * ((s.specific_force_b_m_s2 - prev_.specific_force_b_m_s2).squaredNorm() / 3.0 - accel_diff_var_);
    gyro_diff_var_ += a * ((s.angular_rate_b_rad_s - prev_.angular_rate_b_rad_s).squaredNorm() / 3.0 - gyro_diff_var_);
    // per-sample variance var(diff)/2, as a density: sigma^2 * sample period
    in.accel_white_floor_m_s2_rthz = std::sqrt(0.5 * accel_diff_var_ * period_.seconds());
    in.gyro_white_floor_rad_s_rthz = std::sqrt(0.5 * gyro_diff_var_ * period_.seconds());
  }
  predict_.add(in);
  if (predict_.pending_s() >= cfg_.covariance_period_s - 1e-9) predict_.flush(filter_);
  widen_for_imu_errors(s, dt);
  const double a = std::min(1.0, dt / 1.0);
  horizontal_accel_m_s2_ += a * (f_n.head<2>().norm() - horizontal_accel_m_s2_);
  const Eigen::Index yaw = filter_.layout().att.start + 2;
  if (!mag_sees_heading(s.t_s) && horizontal_accel_m_s2_ < cfg_.yaw_observable_accel_m_s2 &&
      filter_.P()(yaw, yaw) > cfg_.yaw_freeze_sigma_rad * cfg_.yaw_freeze_sigma_rad) {
    frozen_.set(static_cast<std::size_t>(yaw));
    // Without a magnetometer to see the heading, nor the errors of the gyros
    // that turn it (the axes near vertical): their estimate is integrated
    // into the heading as surely as an update would move it.
    if (!mag_live(s.t_s)) {
      const Eigen::Matrix3d C = nav_.C_nb();
      for (Eigen::Index i = 0; i < 3; ++i) {
        if (std::abs(C(2, i)) > cfg_.yaw_gyro_vertical_cos) filter_.add_axis_states(sensor_axis::kFirstGyro + i, frozen_);
      }
    }
  }
  // The latency is seen through the acceleration, which a gap leaves unknown.
  if (s.t_s - last_gap_t_s_ < cfg_.latency_freeze_after_gap_s) freeze(Effect::GpsLatency);
  if (holding_gps_bias(s.t_s)) freeze(Effect::GpsPositionBias);

  fuse_due_gnss(s.t_s, dt, r1);
  fuse_magnetometer(s, r1);
  ImuSample compensated = s;
  compensated.specific_force_b_m_s2 = r1.specific_force_b_m_s2;
  compensated.angular_rate_b_rad_s = r1.angular_rate_b_rad_s;
  stillness_.add(compensated, dt);
  if (cfg_.vehicle == VehicleKind::Auto) {
    const bool was_ground = ground_vehicle();
    vehicle_.add(nav_, dt, s.t_s - last_gnss_pos_t_s_ < 1.0);
    if (ground_vehicle() != was_ground) {
      events_ |= nav_flag::kVehicleChanged;
      if (vehicle_.on_bracket()) {
        predict_.flush(filter_);
        filter_.start_vehicle_mount(cfg_.vehicle_mount_sigma_rad);
      }
    }
  }
  fuse_vehicle_constraints(s, r1);
  update_health(s.t_s, dt);
  prev_ = s;
  out_.angular_rate_b_rad_s = r1.angular_rate_b_rad_s;
  emit();
}

void Navigator::align(const ImuSample& s, double dt) {
  if (scale_check_.refused()) return;  // the data's units are wrong throughout
  ImuSample corrected = s;  // the heading from the field the known magnetometer model implies
  if (s.has_mag) corrected.mag_b_uT = filter_.mag_field_b_uT(s.mag_b_uT);
  alignment_.add_imu(corrected, dt);
  scale_check_.add_sample(s.specific_force_b_m_s2, s.angular_rate_b_rad_s, dt);
  AlignmentResult res;
  const double latency = filter_.gps_latency_s();
  while (!gnss_.empty() && gnss_.front().arrival_s - latency <= s.t_s) {
    const GnssObservation z = gnss_.front();
    gnss_.pop();
    if (z.has_velocity) scale_check_.add_gnss_velocity(z.arrival_s - latency, z.v_ne_m_s);
    if (!scale_check_.gyro_plausible(s.t_s, z.has_velocity ? z.v_ne_m_s.norm() : NAN)) continue;
    if (!z.has_height) continue;  // the INS starts from a 3-D fix
    if (!alignment_.add_gnss(z, s.t_s, res)) continue;
    if (!scale_check_.accel_plausible(wgs84::normal_gravity_m_s2(res.nav.lat_rad, res.nav.h_m))) return;
    alignment_result_ = res;
    nav_ = res.nav;
    filter_.seed_attitude(res.att_sigma_rad);
    filter_.reset_block(filter_.layout().vel, res.vel_sigma_m_s);
    // A restart's biases refer to the temperature they were learnt at.
    filter_.set_reference_temperature(warm_.given ? warm_.temp_ref_degC : res.temp_ref_degC);
    if (res.field_corrected_by_saved_iron) keep_saved_iron();  // the heading came from it
    // The rate was measured at the rest's specific force, or in motion on the
    // window's average, about gravity's.
    const Eigen::Vector3d f_b = res.at_rest ? res.rest_specific_force_b_m_s2
                                            : Eigen::Vector3d(nav_.C_nb().transpose() *
                                                              Eigen::Vector3d(0.0, 0.0, -wgs84::kStandardGravity));
    filter_.seed_gyro_bias(res.gyro_bias_rad_s, f_b, res.gyro_bias_sigma_rad_s);
    if (res.at_rest) {
      // Floor: normal gravity against the site's true gravity (anomalies ~1e-3 g).
      const double sigma_along = std::max(res.rest_specific_force_sigma_m_s2, 0.01);
      if (warm_.given) keep_saved_biases(res.rest_specific_force_b_m_s2, sigma_along);
      filter_.correlate_gyro_bias_at_rest(nav_, res.rest_specific_force_b_m_s2);
      filter_.seed_accel_bias_at_rest(nav_, res.rest_specific_force_b_m_s2, sigma_along);
    }
    filter_.set_gps_bias_sigma(z.sigma_ned_m, 0.0, white_scale(z));
    // The receiver's correlated error as the unit knew it before the restart,
    // on each axis where that says more than this fix's level (the GM's
    // stationary sigma): the fix below then places the INS where the fix
    // minus that error says. (A saved sigma above the level is no knowledge:
    // taken anyway, the real quadcopter's bias state, 5.8 m wide where its
    // fixes now said 0.3 m, took up 10 m of the INS's drift.)
    if (warm_.given && warm_.effects[static_cast<std::size_t>(Effect::GpsPositionBias)].given) {
      EffectPrior p = warm_.effects[static_cast<std::size_t>(Effect::GpsPositionBias)];
      const Eigen::Vector3d level = filter_.gps_bias_sigma_ned_m();
      for (std::size_t i = 0; i < 3; ++i) keep_tighter(p, i, 0.0, level(static_cast<Eigen::Index>(i)));
      filter_.set_prior(Effect::GpsPositionBias, p);
    }
    seed_position_on_fix(z, s.t_s - (z.arrival_s - latency));
    recovery_.restart(s.t_s);
    vertical_.restart();
    heading_.restart();
    last_gnss_pos_t_s_ = s.t_s;
    events_ |= nav_flag::kAlignedNow;
    if (alignment_.checking_course()) filter_at_alignment_ = filter_;
    return;
  }
  // Not aligned yet: why the field gave no heading, should it stay so.
  alignment_result_.field_ratio = alignment_.field_ratio();
  alignment_result_.dip_difference_rad = alignment_.dip_difference_rad();
  alignment_result_.saved_iron_refused = alignment_.saved_iron_refused();
}

void Navigator::widen_for_imu_errors(const ImuSample& s, double dt) {
  // The interval touches a sample at full scale: its unknown error grows the
  // covariance. Samples the prefilter mixed a clipped input into carry it
  // smeared, not more of it (the wavelet's gain is 1): they only freeze the
  // biases and raise the flag.
  const std::uint8_t clipped = s.clipped_axes | prev_.clipped_axes;
  const std::uint8_t touched = clipped | s.clip_reach_axes | prev_.clip_reach_axes;
  const bool gap = dt > cfg_.gap_periods * period_.seconds();
  if (touched || gap) predict_.flush(filter_);  // the extra noise belongs after this interval
  const Eigen::Matrix3d C = nav_.C_nb();
  Eigen::Vector3d var_f = Eigen::Vector3d::Zero(), var_w = Eigen::Vector3d::Zero();
  frozen_.reset();
  for (std::size_t a = 0; a < kSensorAxes; ++a) {
    const auto i = static_cast<Eigen::Index>(a % 3);
    const bool accel = a < 3;
    if ((static_cast<unsigned>(clipped) >> a) & 1u) {
      // The true value is beyond the converter: an unknown error, constant
      // over the burst, so its velocity (attitude) error grows as k dt and the
      // variance by sigma^2 (2k+1) dt^2 per interval.
      const double range = accel ? cfg_.screen.accel_range_m_s2 : cfg_.screen.gyro_range_rad_s;
      const double v = std::abs(accel ? s.specific_force_b_m_s2(i) : s.angular_rate_b_rad_s(i));
      const double sigma = cfg_.clip_error_fraction * std::max(range, v);
      const double k = static_cast<double>(clip_run_[a]++);
      (accel ? var_f : var_w)(i) += sigma * sigma * (2.0 * k + 1.0) * dt * dt;
    } else {
      clip_run_[a] = 0;
    }
    if ((static_cast<unsigned>(touched) >> a) & 1u) last_clip_t_s_[a] = s.t_s;
    if (s.t_s - last_clip_t_s_[a] < cfg_.clip_hold_s) filter_.add_axis_states(static_cast<Eigen::Index>(a), frozen_);
  }
  if (gap) {  // the motion inside the gap is unknown beyond the straight line through its ends
    const double sa = cfg_.gap_accel_sigma_m_s2 + 0.5 * (s.specific_force_b_m_s2 - prev_.specific_force_b_m_s2).norm();
    const double sw = cfg_.gap_rate_sigma_rad_s + 0.5 * (s.angular_rate_b_rad_s - prev_.angular_rate_b_rad_s).norm();
    var_f.array() += sa * sa * dt * dt;
    var_w.array() += sw * sw * dt * dt;
  }
  // The gyro's scale factor, in no state unless gyro_scale is carried (navigator.hpp).
  if (!filter_.layout().has(Effect::GyroScale))
    var_w += (cfg_.gyro_scale_noise_rt_s * s.angular_rate_b_rad_s).cwiseAbs2() * dt;
  if (var_f.any()) filter_.add_block_noise(filter_.layout().vel, C * var_f.asDiagonal() * C.transpose());
  if (var_w.any()) filter_.add_block_noise(filter_.layout().att, C * var_w.asDiagonal() * C.transpose());
}

void Navigator::freeze(Effect e) {
  const Slice& states = filter_.layout().of(e);
  if (!states.active()) return;
  for (Eigen::Index i = 0; i < states.size; ++i) frozen_.set(static_cast<std::size_t>(states.start + i));
}

void Navigator::disturbed(double t_s) {
  if (!holding_gps_bias(t_s)) ++counters_.gnss_bias_holds;  // a new hold
  disturbed_t_s_ = t_s;
  freeze(Effect::GpsPositionBias);  // from this update on (process() renews it each sample)
}

void Navigator::begin_reset(double t_meas) {
  predict_.flush(filter_);
  if (counters_.resets() == 0) counters_.first_reset_t_s = t_meas;
}

void Navigator::release_gyro_bias_about_vertical() {
  const StateLayout& L = filter_.layout();
  if (!L.has(Effect::GyroBias)) return;
  const Eigen::Vector3d down_b = nav_.C_nb().row(2).transpose();
  const double w = cfg_.heading_bias_widen_rad_s;
  filter_.add_block_noise(L.of(Effect::GyroBias), w * w * down_b * down_b.transpose());
  ++counters_.gyro_bias_releases;
  events_ |= nav_flag::kGyroBiasReleased;
}

bool Navigator::fuse(AidingSource src, const Measurement& m, double t_meas) {
  predict_.flush(filter_);  // P to the time of this update
  InnovationRecord rec;
  rec.t_s = t_meas;
  rec.source = src;
  rec.result = fuse_measurement(filter_.P(), dx_, m, frozen_);
  last_result_ = rec.result;
  const auto i = static_cast<std::size_t>(src);
  test_ratio_[i] = rec.result.test_ratio.head(rec.result.rows).maxCoeff();
  static constexpr std::uint32_t kFused[] = {nav_flag::kGnssPosFused, nav_flag::kGnssVelFused, nav_flag::kMagFused, 0,
                                             nav_flag::kNonholonomicFused};
  static constexpr std::uint32_t kRejected[] = {nav_flag::kGnssPosRejected, nav_flag::kGnssVelRejected,
                                                nav_flag::kMagRejected, 0, 0};
  if (rec.result.accepted) {
    ++counters_.accepted[i];
    events_ |= kFused[i];
    filter_.feedback(dx_, nav_);
    // An epoch can be fused only while the horizon still holds its time of
    // validity: a latency estimate beyond it would make every later epoch late.
    // Below zero the fix is valid after it arrived on the IMU's clock: the
    // IMU's stamps are late (imu_latency_s), which diagnose reports.
    filter_.set_gps_latency(std::clamp(filter_.gps_latency_s(), kMinGpsLatency_s, max_gps_latency_s()));
  } else {
    ++counters_.rejected[i];
    events_ |= kRejected[i];
  }
  if (observer_) observer_->on_innovation(rec);
  return rec.result.accepted;
}

void Navigator::update_health(double t_now, double dt) {
  std::uint32_t f = 0;
  for (std::size_t a = 0; a < kSensorAxes; ++a)
    if (t_now - last_clip_t_s_[a] < cfg_.clip_hold_s) f |= nav_flag::kClipping;
  const bool timeout = t_now - last_gnss_pos_t_s_ > cfg_.gnss_timeout_s;
  if (timeout) {
    f |= nav_flag::kGnssTimeout;
    counters_.gnss_timeout_total_s += dt;
    if (!in_timeout_) ++counters_.gnss_timeouts;
  }
  in_timeout_ = timeout;
  if (mag_started_ && !mag_live(t_now)) f |= nav_flag::kMagTimeout;
  if (recovery_.lost(t_now)) {
    f |= nav_flag::kLost;
    if (counters_.lost_total_s == 0.0) counters_.first_lost_t_s = t_now;
    counters_.lost_total_s += dt;
  }
  if (recovery_.gnss_suspect(t_now)) f |= nav_flag::kGnssSuspect;
  if (still_now_) f |= nav_flag::kStill;
  if (ground_vehicle()) f |= nav_flag::kGroundVehicle;
  state_flags_ = f;
}

void Navigator::emit() {
  const std::uint32_t flags = state_flags_ | events_ | (aligned() ? nav_flag::kAligned : 0u);
  events_ = 0;
  if (!observer_) return;
  // P is the last prediction's: at most covariance_period_s old.
  out_.nav = nav_;
  out_.flags = flags;
  out_.test_ratio = test_ratio_;
  const StateLayout& L = filter_.layout();
  out_.P_nav = filter_.P().block(L.pos.start, L.pos.start, kNavStates, kNavStates);
  for (Eigen::Index a = 0; a < kSensorAxes; ++a) {
    const auto k = static_cast<std::size_t>(a);
    out_.sensor_error[k] = filter_.sensor_error(a);
    out_.sensor_error_sigma[k] = filter_.sensor_error_sigma(a);
  }
  observer_->on_nav(out_);
}

}  // namespace sinu::est
