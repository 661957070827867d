#include "estimator/nav/navigator.hpp"

#include <algorithm>
#include <cmath>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ekf/aiding/declination/declination.hpp"
#include "estimator/ekf/aiding/field_model/field_model.hpp"
#include "estimator/ekf/aiding/gnss_position/gnss_position.hpp"
#include "estimator/ekf/aiding/gnss_velocity/gnss_velocity.hpp"
#include "estimator/ekf/aiding/magnetometer/magnetometer.hpp"
#include "estimator/ekf/aiding/zero_velocity/zero_velocity.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

namespace {

constexpr double kNever = -1e300;

/// The layout the configuration asks for: the magnetometer's states reserved
/// (deferred) when it is to be used, dropped when not.
/// The magnetometer's states: reserved, and switched on by its first field sample.
constexpr Effect kMagEffects[] = {Effect::MagEarthField, Effect::MagHardIron, Effect::MagSoftIron,
                                  Effect::MagMisalign};

/// A restart's prior, component k: kept where tighter than what the unit
/// would start from without it (cold_value, cold_sigma), else that: a saved
/// sigma that has grown past it is no knowledge.
void keep_tighter(EffectPrior& saved, std::size_t k, double cold_value, double cold_sigma) {
  if (saved.sigma[k] < cold_sigma) return;
  saved.value[k] = cold_value;
  saved.sigma[k] = cold_sigma;
}

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
  last_gap_t_s_ = -1e300;
  horizon_now_s_ = cfg.horizon_s;
  raw_period_s_ = period_s_ = horizontal_accel_m_s2_ = accel_diff_var_ = gyro_diff_var_ = 0.0;
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
  if (have_raw_) {  // nominal raw period: gaps and repeats do not move it
    const double dt = raw.t_s - last_raw_t_s_;
    if (raw_period_s_ == 0.0 || dt < 0.5 * raw_period_s_) raw_period_s_ = dt;
    else if (dt < 2.0 * raw_period_s_) raw_period_s_ += 0.02 * (dt - raw_period_s_);
  }
  have_raw_ = true;
  last_raw_t_s_ = raw.t_s;
  if (s.clipped_axes) {
    ++counters_.imu_clipped_samples;
    // A clipped input reaches every prefilter output up to its delay later.
    const double reach = s.t_s + prefilter_->delay_samples() * raw_period_s_ + 1e-9;
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
  if (period_s_ == 0.0 || dt < 0.5 * period_s_) period_s_ = dt;
  else if (dt < 2.0 * period_s_) period_s_ += 0.02 * (dt - period_s_);
  if (dt > cfg_.gap_periods * period_s_) {
    ++counters_.imu_gaps;
    counters_.imu_gap_total_s += dt;
    counters_.imu_longest_gap_s = std::max(counters_.imu_longest_gap_s, dt);
    events_ |= nav_flag::kImuGap;
  }
  if (!aligned()) {
    align(s, dt);
    prev_ = s;
    if (aligned()) emit();
    return;
  }

  alignment_.add_imu(s, dt);  // after a course alignment, its check (check_course)
  const bool gap = dt > cfg_.gap_periods * period_s_;
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
    in.accel_white_floor_m_s2_rthz = std::sqrt(0.5 * accel_diff_var_ * period_s_);
    in.gyro_white_floor_rad_s_rthz = std::sqrt(0.5 * gyro_diff_var_ * period_s_);
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
  const Slice latency = filter_.layout().of(Effect::GpsLatency);
  if (latency.active() && s.t_s - last_gap_t_s_ < cfg_.latency_freeze_after_gap_s) {
    frozen_.set(static_cast<std::size_t>(latency.start));
  }

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
      filter_.correlate_gyro_bias_at_rest(nav_, res.rest_specific_force_b_m_s2);
      filter_.seed_accel_bias_at_rest(nav_, res.rest_specific_force_b_m_s2,
                                      std::max(res.rest_specific_force_sigma_m_s2, 0.01));
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

std::array<EffectPrior, kEffectCount> Navigator::saved_iron() const {
  std::array<EffectPrior, kEffectCount> iron{};
  for (std::size_t e = 0; e < kEffectCount; ++e)
    if (checked_by_the_field(static_cast<Effect>(e))) iron[e] = warm_.effects[e];
  return iron;
}

void Navigator::offer_saved_iron() {
  const std::array<EffectPrior, kEffectCount> iron = saved_iron();
  if (std::none_of(iron.begin(), iron.end(), [](const EffectPrior& p) { return p.given; })) return;
  // Both corrections are affine in the reading (A^-1 (m - h)): the saved
  // iron's reading of the field is an affine map of the current one's, which
  // the rest's mean field is.
  const auto affine = [&](const std::array<EffectPrior, kEffectCount>& with, Eigen::Matrix3d& M, Eigen::Vector3d& c) {
    c = filter_.mag_field_b_uT(Eigen::Vector3d::Zero(), with);
    for (Eigen::Index i = 0; i < 3; ++i) M.col(i) = filter_.mag_field_b_uT(Eigen::Vector3d::Unit(i), with) - c;
  };
  Eigen::Matrix3d now_M, saved_M;
  Eigen::Vector3d now_c, saved_c;
  affine({}, now_M, now_c);
  affine(iron, saved_M, saved_c);
  const Eigen::Matrix3d A = saved_M * now_M.inverse();
  alignment_.set_saved_iron_field(A, saved_c - A * now_c);
}

void Navigator::keep_saved_iron() {
  const std::array<EffectPrior, kEffectCount> iron = saved_iron();
  for (std::size_t e = 0; e < kEffectCount; ++e) {
    const auto effect = static_cast<Effect>(e);
    if (!iron[e].given) continue;
    EffectPrior p = iron[e];
    // One attitude's strength and dip cannot see every shift of the iron
    // (one across the horizontal field turns the heading and keeps both):
    // the hard iron is held to no better than the field the alignment trusts.
    if (effect == Effect::MagHardIron)
      for (std::size_t k = 0; k < 3; ++k) p.sigma[k] = std::max(p.sigma[k], cfg_.alignment.mag_residual_field_uT);
    filter_.set_prior(effect, p);
  }
}

NoiseAdapterConfig Navigator::white_scale_config() const {
  NoiseAdapterConfig white = cfg_.gnss_white_scale;  // at most all white
  white.max_sigma = std::min(white.max_sigma, 1.0 / std::sqrt(1.0 - cfg_.tuning.gps_bias_variance_fraction));
  return white;
}

WarmStart Navigator::warm_state() const {
  WarmStart w;
  if (!aligned()) return w;
  w.given = true;
  const StateLayout& L = filter_.layout();
  for (std::size_t e = 0; e < kEffectCount; ++e) {
    const auto effect = static_cast<Effect>(e);
    // The Earth field's state is the invariant error of this solution's
    // attitude; a restart starts it again from a sample (start_mag_field).
    if (!L.has(effect) || effect == Effect::MagEarthField) continue;
    EffectPrior& p = w.effects[e];
    p.given = true;
    for (Eigen::Index i = 0; i < kEffectDims[e]; ++i) {
      p.value[static_cast<std::size_t>(i)] = filter_.effect(effect, i);
      p.sigma[static_cast<std::size_t>(i)] = filter_.effect_sigma(effect, i);
    }
  }
  w.temp_ref_degC = filter_.reference_temperature();
  w.gps_bias_level_ned_m = filter_.gps_bias_sigma_ned_m();
  w.gnss_velocity_sigma_m_s = vel_noise_started_ ? vel_noise_.sigma() : 0.0;
  w.mag_sigma_uT = mag_started_ ? mag_noise_.sigma() : 0.0;
  w.gnss_white_scale = gnss_white_scale();
  w.gnss_position_scale = gnss_position_scale();
  return w;
}

bool Navigator::warm_start(const WarmStart& saved, double age_s) {
  if (!saved.given || aligned()) return false;
  warm_ = aged(saved, age_s, filter_.tuning());
  const StateLayout& L = filter_.layout();
  for (std::size_t e = 0; e < kEffectCount; ++e) {
    const auto effect = static_cast<Effect>(e);
    EffectPrior& w = warm_.effects[e];
    if (!w.given) continue;
    if (!L.carries(effect)) {  // this unit is configured without it
      w.given = false;
      continue;
    }
    if (checked_by_the_field(effect)) continue;  // at the alignment, by the field (offer_saved_iron)
    // Per component, against the prior this unit would start from (a model
    // file's, else the vocabulary's).
    const EffectPrior& cold = filter_.tuning().prior[e];
    for (std::size_t k = 0; k < static_cast<std::size_t>(kEffectDims[e]); ++k) {
      keep_tighter(w, k, cold.given ? cold.value[k] : filter_.effect(effect, static_cast<Eigen::Index>(k)),
                   cold.given ? cold.sigma[k] : filter_.tuning().initial_sigma[e]);
    }
    filter_.set_prior(effect, w);
  }
  offer_saved_iron();
  // Learnt noise levels, where this unit learns them (a sigma the user gave stays).
  if (cfg_.gnss_velocity_noise.enabled && warm_.gnss_velocity_sigma_m_s > 0.0) {
    vel_noise_.configure(cfg_.gnss_velocity_noise, warm_.gnss_velocity_sigma_m_s);
    vel_noise_started_ = true;
  }
  if (cfg_.mag_noise.enabled && warm_.mag_sigma_uT > 0.0) mag_noise_.configure(cfg_.mag_noise, warm_.mag_sigma_uT);
  if (cfg_.gnss_white_scale.enabled && warm_.gnss_white_scale.minCoeff() > 0.0) {
    white_h_.configure(white_scale_config(), warm_.gnss_white_scale.x());
    white_v_.configure(white_scale_config(), warm_.gnss_white_scale.y());
  }
  if (cfg_.gnss_position_scale.enabled && warm_.gnss_position_scale.minCoeff() > 0.0) {
    pos_scale_h_.configure(cfg_.gnss_position_scale, warm_.gnss_position_scale.x());
    pos_scale_v_.configure(cfg_.gnss_position_scale, warm_.gnss_position_scale.y());
  }
  return true;
}

void Navigator::widen_for_imu_errors(const ImuSample& s, double dt) {
  // The interval touches a sample at full scale: its unknown error grows the
  // covariance. Samples the prefilter mixed a clipped input into carry it
  // smeared, not more of it (the wavelet's gain is 1): they only freeze the
  // biases and raise the flag.
  const std::uint8_t clipped = s.clipped_axes | prev_.clipped_axes;
  const std::uint8_t touched = clipped | s.clip_reach_axes | prev_.clip_reach_axes;
  const bool gap = dt > cfg_.gap_periods * period_s_;
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

void Navigator::fuse_due_gnss(double t_now, double dt, const BodyRates& now) {
  while (!gnss_.empty()) {
    GnssObservation z = gnss_.front();
    const double t_meas = z.arrival_s - filter_.gps_latency_s();
    if (t_meas > t_now) break;
    gnss_.pop();
    const double dt_back = t_now - t_meas;
    // Later than one IMU interval (plus slack for jitter) means the horizon missed it.
    if (dt_back > 1.5 * dt + 1e-3) {
      ++counters_.gnss_late;
      if (z.has_position) recovery_.on_unusable(t_now);
      continue;
    }
    check_course(z, t_now, dt_back);
    if (z.has_position) {
      if (!z.sigma_is_guess) {
        last_stated_sigma_ned_m_ = z.sigma_ned_m;
        last_stated_t_s_ = t_meas;
      } else if (t_meas - last_stated_t_s_ <= cfg_.stated_sigma_hold_s) {
        z.sigma_ned_m = last_stated_sigma_ned_m_;  // a receiver that skipped its GST this once
        z.sigma_is_guess = false;
      } else {
        z.sigma_ned_m.head<2>() *= pos_scale_h_.sigma();
        z.sigma_ned_m.z() *= pos_scale_v_.sigma();
      }
      filter_.set_gps_bias_sigma(z.sigma_ned_m, t_meas - last_gnss_pos_t_s_, white_scale(z));
      last_gnss_pos_t_s_ = t_meas;
      bool ok = fuse(AidingSource::GnssPosition,
                     gnss_position_measurement(filter_, nav_, dt_back, z, cfg_.gate_sigma), t_meas);
      const double innovation_h = last_result_.innovation.head<2>().norm();
      if (!ok && !recovery_.is_jump(innovation_h, z.sigma_ned_m.head<2>().norm()) &&
          last_result_.innovation.head(last_result_.rows).allFinite()) {
        // A misfit too small to be a GNSS jump: the filter claimed more than it
        // knew. Widen the position by the misfit and fuse the epoch again
        // (no waiting for a reset while a centimetre receiver is ignored).
        const Eigen::Vector3d y = last_result_.innovation;
        filter_.add_block_noise(filter_.layout().pos, y.cwiseAbs2().asDiagonal());
        ++counters_.position_inflations;
        ok = fuse(AidingSource::GnssPosition, gnss_position_measurement(filter_, nav_, dt_back, z, cfg_.gate_sigma),
                  t_meas);
      }
      // A fix without a height (its GGA missing or corrupt, or a receiver
      // without one) is fused north and east; it neither resets the solution
      // (a reset seeds the position from a 3-D fix) nor checks the vertical.
      if (z.has_height) {
        learn_position_noise(z, t_meas);
        recover(recovery_.on_position(t_meas, ok, innovation_h, z.sigma_ned_m.head<2>().norm()), z, dt_back, t_meas);
        check_vertical(z, t_meas);
      } else if (ok) {
        ++counters_.horizontal_fixes;
      }
    }
    if (z.has_velocity) {
      last_gnss_speed_m_s_ = z.v_ne_m_s.norm();
      const double course = std::atan2(z.v_ne_m_s.y(), z.v_ne_m_s.x()), dt_c = t_meas - course_t_s_;
      if (last_gnss_speed_m_s_ < cfg_.course_min_speed_m_s) {
        course_t_s_ = kNever;
      } else {
        if (dt_c > 0.0 && dt_c < 1.5) {
          const double rate = std::abs(wrap_pi(course - course_rad_)) / dt_c;
          course_rate_rad_s_ += std::min(1.0, dt_c / 1.0) * (rate - course_rate_rad_s_);
        } else {
          course_rate_rad_s_ = 1e9;  // not known yet
        }
        course_rad_ = course;
        course_t_s_ = t_meas;
      }
    }
    if (z.has_velocity && cfg_.fuse_velocity) {
      if (!vel_noise_started_) {  // the first epoch's sigma is the starting value
        vel_noise_.configure(cfg_.gnss_velocity_noise, z.sigma_vel_m_s);
        vel_noise_started_ = true;
        last_vel_update_t_s_ = t_meas;
      }
      GnssObservation zv = z;
      zv.sigma_vel_m_s = vel_noise_.sigma();
      if (z.course_held) {
        // A speed without a direction: the velocity is zero within that
        // speed (course_hold.hpp); neither the noise learner nor the recovery
        // takes it for the receiver's velocity.
        zv.v_ne_m_s.setZero();
        zv.sigma_vel_m_s = std::hypot(zv.sigma_vel_m_s, z.v_ne_m_s.norm());
      }
      const bool ok = fuse(AidingSource::GnssVelocity,
                           gnss_velocity_measurement(filter_, nav_, now.angular_rate_b_rad_s, accel_n_,
                                                     velocity_lag_accel(t_meas), dt_back, zv, cfg_.gate_sigma),
                           t_meas);
      if (!z.course_held) {
        vel_noise_.learn(last_result_, t_meas - last_vel_update_t_s_);
        last_vel_update_t_s_ = t_meas;
        recover(recovery_.on_velocity(t_meas, ok, z.v_ne_m_s.norm()), z, dt_back, t_meas);
      }
    }
  }
}

// The latest position update teaches the factor on its sigma: on the whole
// of a guessed one, on the white part of a stated one (rows N, E
// horizontally; D vertically).
void Navigator::learn_position_noise(const GnssObservation& z, double t_meas) {
  if (last_result_.rows < 3) return;
  // Without the correlated-error states the whole stated variance is white.
  if (!z.sigma_is_guess && !filter_.layout().has(Effect::GpsPositionBias)) return;
  const double dt = last_pos_scale_t_s_ == kNever ? 0.0 : t_meas - last_pos_scale_t_s_;
  NoiseAdapter& h = z.sigma_is_guess ? pos_scale_h_ : white_h_;
  NoiseAdapter& v = z.sigma_is_guess ? pos_scale_v_ : white_v_;
  h.learn_scale(last_result_, 0, 2, dt);
  v.learn_scale(last_result_, 2, 1, dt);
  last_pos_scale_t_s_ = t_meas;
}

Eigen::Vector3d Navigator::white_scale(const GnssObservation& z) const {
  if (z.sigma_is_guess) return Eigen::Vector3d::Ones();  // the whole sigma is scaled instead
  return {white_h_.sigma(), white_h_.sigma(), white_v_.sigma()};
}

void Navigator::begin_reset(double t_meas) {
  predict_.flush(filter_);
  if (counters_.resets() == 0) counters_.first_reset_t_s = t_meas;
}

void Navigator::check_vertical(const GnssObservation& z, double t_meas) {
  const StateLayout& L = filter_.layout();
  const Eigen::Index vd = L.vel.start + 2;
  VerticalRate rate;
  if (!vertical_.push(t_meas, z.h_m, nav_.v_n_m_s.z(), std::sqrt(filter_.P()(vd, vd)), rate)) return;
  begin_reset(t_meas);
  nav_.v_n_m_s.z() = rate.vd_m_s;
  filter_.reset_state(vd, std::hypot(rate.sigma_m_s, cfg_.vertical_reset_sigma_m_s));
  if (L.has(Effect::AccelBias)) {
    // The bias along gravity has shifted: let it move (PX4 EKF2's bad_acc_vertical).
    const Eigen::Vector3d down_b = nav_.C_nb().row(2).transpose();
    const double s = cfg_.vertical_bias_widen_m_s2;
    filter_.add_block_noise(L.of(Effect::AccelBias), s * s * down_b * down_b.transpose());
  }
  ++counters_.velocity_resets;
  ++counters_.vertical_resets;
  events_ |= nav_flag::kVelocityReset;
}

Eigen::Vector3d Navigator::velocity_lag_accel(double t_meas) const {
  if (!filter_.layout().of(Effect::GpsVelocityLatency).active()) return accel_n_;
  const double tau_s = filter_.view(Effect::GpsVelocityLatency).scalar();
  Eigen::Vector3d mean = accel_n_;
  if (!velocity_history_.mean_accel(t_meas, tau_s, mean)) return accel_n_;
  // Over a few samples the mean is the IMU's vibration: below ~0.05 s the smoothed one takes over.
  const double w = std::clamp((tau_s - 0.03) / 0.05, 0.0, 1.0);
  return w * mean + (1.0 - w) * accel_n_;
}

double Navigator::turn_rate_rad_s(double t_s) const {
  return t_s - course_t_s_ <= 1.0 ? course_rate_rad_s_ : yaw_rate_rad_s_;
}

void Navigator::check_heading(double t_meas) {
  const StateLayout& L = filter_.layout();
  const Eigen::Vector3d x_n = nav_.C_nb().col(0);  // the body's nose
  const double yaw = std::atan2(x_n.y(), x_n.x()), dt_yaw = t_meas - heading_yaw_t_s_;
  yaw_rate_rad_s_ = dt_yaw > 0.0 && dt_yaw < 1.0 ? std::abs(wrap_pi(yaw - heading_yaw_rad_)) / dt_yaw
                                                 : 1e9;
  heading_yaw_rad_ = yaw;
  heading_yaw_t_s_ = t_meas;
  if (last_result_.rows != 3 || !L.has(Effect::GyroBias)) return;
  // The reading's change for a turn of the heading by one radian.
  const Eigen::Vector3d F = filter_.mag_earth_field_n_uT();
  const Eigen::Vector3d turn_b = filter_.mag_axes() * (nav_.C_nb().transpose() * Eigen::Vector3d(-F.y(), F.x(), 0.0));
  const double n2 = turn_b.squaredNorm();
  if (!(n2 > 1e-6)) return;
  const double misfit = turn_b.dot(last_result_.innovation) / n2;
  const double sigma = turn_b.cwiseProduct(last_result_.innovation_sigma).norm() / n2;
  // Judged on straight legs only: while the heading turns, a field model that
  // is not quite right (a soft iron the model lacks) misfits by an amount that
  // follows the heading, and the filter lags it by a few degrees one-signed
  // for the turn's duration (released 8-9 times per flight, attitude 1.6 ->
  // 2.2 deg, on the diagnose evaluation's soft-iron flights). The turn rate is
  // the GNSS course's when moving (a shifted gyro would turn the INS's own).
  if (turn_rate_rad_s(t_meas) > cfg_.heading_check_max_turn_rad_s) {
    heading_.restart();
    return;
  }
  if (!heading_.push(t_meas, misfit, sigma)) return;
  predict_.flush(filter_);
  release_gyro_bias_about_vertical();
}

void Navigator::check_course(const GnssObservation& z, double t_now, double dt_back) {
  double yaw = 0.0, sigma = 0.0;
  if (!alignment_.check_course(z, t_now, yaw, sigma)) return;
  const Eigen::Index i = filter_.layout().att.start + 2;
  predict_.flush(filter_);
  const double turn = wrap_pi(yaw - euler_from_quat(nav_.q_nb).z());
  // The in-motion yaw against the filter's, which has had the GNSS velocity
  // since: within two combined sigmas the course was right; beyond three it
  // was not; between, the next, surer, in-motion yaw decides. (A gentle start
  // pulls the filter's yaw part of the way with a sigma it does not have: 59
  // deg off under a 4-deg sigma, the in-motion yaw at 20 deg.)
  // The contradiction must hold for course_check_persist_s: an in-motion yaw
  // is sure of itself a little early on a real multirotor's vibration (uav_log171
  // without its magnetometer: 35 deg off under a 14-deg sigma, while the EKF,
  // 17 deg off, was turning to the truth on its own in the first dash).
  const double combined = std::hypot(sigma, std::sqrt(filter_.P()(i, i)));
  if (std::abs(turn) <= 2.0 * combined) alignment_.end_course_check();
  if (std::abs(turn) <= 3.0 * combined) {
    course_contradicted_since_s_ = kNever;
    return;
  }
  if (course_contradicted_since_s_ == kNever) course_contradicted_since_s_ = t_now;
  if (t_now - course_contradicted_since_s_ < cfg_.alignment.course_check_persist_s) return;
  alignment_.end_course_check();
  // Seconds under a heading that many degrees off taught the sensor errors
  // the misfit (a 180-deg mount: 0.4 m/s^2 of accelerometer bias, 0.16
  // deg/s of gyro bias; the heading then ran 15 deg away): the filter
  // restarts from its alignment, at the position and velocity it has now,
  // and the field states (if any) restart with the next field sample.
  const Eigen::Index vd = filter_.layout().vel.start + 2;
  const double sigma_vd = std::sqrt(filter_.P()(vd, vd));
  filter_ = filter_at_alignment_;
  mag_started_ = false;
  filter_.reset_yaw(nav_, turn, sigma);
  // And on the fix, as at the alignment: the solution drifted under the wrong heading.
  if (z.has_velocity && !z.course_held) seed_velocity_on_fix(z, sigma_vd);
  if (z.has_position && z.has_height) seed_position_on_fix(z, dt_back);
  alignment_result_.course_turn_rad = turn;
  alignment_result_.course_turn_t_s = t_now;
  events_ |= nav_flag::kCourseTurned;
  heading_.restart();
  // The detector's evidence was the body velocity under the wrong heading (a
  // car it had already found kept its heading, and the check agreed).
  if (vehicle_.guess() == VehicleGuess::Undecided) vehicle_.restart();
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

void Navigator::recover(RecoveryAction action, const GnssObservation& z, double dt_back, double t_meas) {
  if (action == RecoveryAction::None) return;
  vertical_.restart();
  heading_.restart();
  begin_reset(t_meas);
  const StateLayout& L = filter_.layout();
  const double sigma_vd = std::sqrt(filter_.P()(L.vel.start + 2, L.vel.start + 2));
  const bool velocity = z.has_velocity && !z.course_held;  // a held course is no direction (course_hold.hpp)
  if (action == RecoveryAction::ResetVelocityAndYaw && velocity) {
    // Turn the heading by the angle between the INS's and the receiver's ground tracks.
    const Eigen::Vector2d v_ins = nav_.v_n_m_s.head<2>();
    if (v_ins.norm() > cfg_.recovery.yaw_reset_min_speed_m_s) {
      const double dyaw = std::atan2(v_ins.x() * z.v_ne_m_s.y() - v_ins.y() * z.v_ne_m_s.x(), v_ins.dot(z.v_ne_m_s));
      filter_.reset_yaw(nav_, dyaw, 0.3);
      ++counters_.yaw_resets;
      events_ |= nav_flag::kYawReset;
      // A heading lost by this much is a gyro bias about the vertical that
      // moved beyond its walk (nothing else turns the INS away from the
      // ground track): let it move, as the heading check does.
      release_gyro_bias_about_vertical();
    }
  }
  if (velocity) {
    seed_velocity_on_fix(z, sigma_vd);
    ++counters_.velocity_resets;
    events_ |= nav_flag::kVelocityReset;
  }
  if (action == RecoveryAction::ResetPosition) {
    // On the fix: the receiver's correlated error starts again from its level.
    if (L.has(Effect::GpsPositionBias)) {
      filter_.reset_block(L.of(Effect::GpsPositionBias), filter_.gps_bias_sigma_ned_m());
    }
    seed_position_on_fix(z, dt_back);
    ++counters_.position_resets;
    events_ |= nav_flag::kPositionReset;
  }
}

void Navigator::seed_velocity_on_fix(const GnssObservation& z, double sigma_vd_m_s) {
  nav_.v_n_m_s.head<2>() = z.v_ne_m_s;
  filter_.reset_block(filter_.layout().vel, Eigen::Vector3d(z.sigma_vel_m_s, z.sigma_vel_m_s, sigma_vd_m_s));
}

void Navigator::seed_position_on_fix(const GnssObservation& z, double dt_back) {
  // The position that fits the fix exactly (the IMU = antenna - C l, carried
  // forward from the fix's time), its covariance the fix's errors.
  const Measurement m = gnss_position_measurement(filter_, nav_, dt_back, z, cfg_.gate_sigma);
  nav_.move_position_m(-Eigen::Vector3d(m.innovation));  // predicted - measured, NED [m]
  filter_.seed_position_from(m);
}

void Navigator::fuse_magnetometer(const ImuSample& s, const BodyRates& now) {
  if (!cfg_.use_mag || !s.has_mag || !s.mag_b_uT.allFinite()) return;
  last_mag_sample_t_s_ = s.t_s;
  if (!mag_started_) {  // the first field sample switches the reserved states on
    if (!scale_check_.field_plausible(s.mag_b_uT.norm(), alignment_result_.model_field_n_uT.norm())) return;
    predict_.flush(filter_);
    EffectSet mag;
    for (const Effect e : kMagEffects) mag.add(e);
    filter_.activate_deferred(mag);
    const bool hard_iron_given = filter_.tuning().prior[static_cast<std::size_t>(Effect::MagHardIron)].given;
    if (alignment_result_.model_field_n_uT.allFinite() && !hard_iron_given) {
      // The hard iron from the data: what the reading holds beyond the model's
      // field seen with the aligned attitude (its prior sigma stays: the
      // model may be wrong here). The field state then starts at the model's,
      // where the strength and inclination priors below are linear enough.
      const Eigen::Vector3d h = s.mag_b_uT - filter_.mag_axes() * (nav_.C_nb().transpose() *
                                                                  alignment_result_.model_field_n_uT);
      for (Eigen::Index i = 0; i < 3; ++i) filter_.set_effect(Effect::MagHardIron, i, h(i));
    }
    filter_.start_mag_field(nav_, s.mag_b_uT, mag_noise_.sigma());
    // Priors on the field state, fused once: the declination the heading was
    // aligned with (given, or the model's for a field it recognised) is known
    // beyond this flight, the field's direction too; the model's strength and
    // inclination hold the field apart from the hard iron (aiding/field_model).
    const auto fuse_prior = [&](const Measurement& m) {
      if (fuse_measurement(filter_.P(), dx_, m, frozen_).accepted) filter_.feedback(dx_, nav_);
    };
    if (filter_.layout().has(Effect::MagEarthField)) {
      if (std::isfinite(alignment_result_.declination_rad)) {
        fuse_prior(declination_measurement(
            filter_, alignment_result_.declination_rad,
            std::hypot(cfg_.declination_sigma_rad, alignment_result_.declination_drift_rad), 1e9));
      }
      if (alignment_result_.model_field_n_uT.allFinite()) {
        fuse_prior(field_model_measurement(filter_, alignment_result_.model_field_n_uT, cfg_.field_model_sigma_uT,
                                           cfg_.inclination_sigma_rad, 1e9));
      }
      // The soft iron's common scale is the field's strength again: held at
      // zero (aiding/field_model), unless a model file gave the soft iron.
      if (filter_.layout().has(Effect::MagSoftIron) &&
          !filter_.tuning().prior[static_cast<std::size_t>(Effect::MagSoftIron)].given) {
        fuse_prior(soft_iron_scale_measurement(filter_, 1e-3, 1e9));
      }
    }
    mag_started_ = true;
    last_mag_fused_t_s_ = s.t_s;
    return;
  }
  if (s.t_s - last_mag_fused_t_s_ < cfg_.mag_period_s - 1e-6) return;
  const double since = s.t_s - last_mag_fused_t_s_;
  last_mag_fused_t_s_ = s.t_s;
  const bool ok = fuse(AidingSource::Magnetometer,
                       magnetometer_measurement(filter_, nav_, s.mag_b_uT, now, mag_noise_.sigma(),
                                                cfg_.gate_sigma),
                       s.t_s);
  check_heading(s.t_s);
  mag_noise_.learn(last_result_, since);
  if (ok) {
    mag_reject_since_s_ = -1.0;
    return;
  }
  if (mag_reject_since_s_ < 0.0) mag_reject_since_s_ = s.t_s;
  const bool attitude_vouched = recovery_.velocity_agrees(s.t_s);
  if (s.t_s - mag_reject_since_s_ >= cfg_.mag_reanchor_after_s && attitude_vouched) {
    predict_.flush(filter_);
    filter_.reanchor_hard_iron(nav_, s.mag_b_uT, 2.0 * mag_noise_.sigma());
    ++counters_.mag_reanchors;
    heading_.restart();
    mag_reject_since_s_ = -1.0;
  }
}

void Navigator::fuse_vehicle_constraints(const ImuSample& s, const BodyRates& now) {
  // Still: the IMU says so, and so does the receiver's speed when it is
  // recent; without it, the INS's own speed within 3 sigma of standing (a
  // steady straight leg at 45 m/s in a GNSS gap looks as quiet to the IMU).
  const bool gnss_recent = s.t_s - last_gnss_pos_t_s_ < cfg_.gnss_timeout_s;
  const Eigen::Index v = filter_.layout().vel.start;
  const double sigma_vh = std::sqrt(std::max(filter_.P()(v, v), filter_.P()(v + 1, v + 1)));
  const bool slow = gnss_recent ? last_gnss_speed_m_s_ < cfg_.still_max_gnss_speed_m_s
                                : nav_.v_n_m_s.head<2>().norm() < cfg_.still_max_gnss_speed_m_s + 3.0 * sigma_vh;
  const bool still = stillness_.still() && slow;
  still_now_ = still;
  const bool zupt = ground_vehicle() || cfg_.zero_velocity_in_air;
  if (zupt && still && s.t_s - last_zupt_t_s_ >= cfg_.zero_velocity_period_s - 1e-6) {
    last_zupt_t_s_ = s.t_s;
    fuse(AidingSource::ZeroVelocity,
         zero_velocity_measurement(filter_, nav_, cfg_.zero_velocity_sigma_m_s, cfg_.gate_sigma), s.t_s);
  }
  if (!ground_vehicle() || still) return;
  if (nav_.v_n_m_s.head<2>().norm() < cfg_.nonholonomic_min_speed_m_s) return;
  if (s.t_s - last_nhc_t_s_ < cfg_.nonholonomic_period_s - 1e-6) return;
  last_nhc_t_s_ = s.t_s;
  const bool ok = fuse(AidingSource::Nonholonomic,
                       nonholonomic_measurement(filter_, nav_, now.angular_rate_b_rad_s, cfg_.nonholonomic,
                                                cfg_.gate_sigma, nhc_axes()),
                       s.t_s);
  if (cfg_.vehicle == VehicleKind::Auto) {
    vehicle_.on_constraint(s.t_s, ok);
    if (!ground_vehicle()) events_ |= nav_flag::kVehicleChanged;
  }
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
