#include "estimator/nav/navigator.hpp"

#include <cmath>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ekf/aiding/gnss_position/gnss_position.hpp"
#include "estimator/ekf/aiding/gnss_velocity/gnss_velocity.hpp"
#include "estimator/ekf/aiding/magnetometer/magnetometer.hpp"

namespace sinu::est {

namespace {
constexpr double kUngated = 1e9;  // gate [sigma] that accepts any finite innovation
}  // namespace

void Navigator::init(const NavigatorConfig& cfg, NavObserver* observer, ImuPrefilter* prefilter) {
  cfg_ = cfg;
  observer_ = observer;
  prefilter_ = prefilter ? prefilter : &pass_through_;
  imu_.clear();
  gnss_.clear();
  alignment_.configure(cfg.alignment);
  have_prev_ = false;
  have_raw_ = false;
  mag_started_ = false;
  predict_.clear();
  counters_ = {};
  nav_ = {};
  filter_.init(StateLayout::make(cfg.noise.order(), cfg.effects), cfg.noise, cfg.tuning, cfg.initial);
  filter_.set_lever_arm(cfg.lever_arm_b_m);
  filter_.set_gps_latency(cfg.gps_latency_s);
  dx_ = StateVec::Zero(filter_.layout().dim);
}

void Navigator::push_imu(const ImuSample& raw) {
  // Checked before the prefilter: one NaN would poison a wavelet's registers.
  if (!raw.specific_force_b_m_s2.allFinite() || !raw.angular_rate_b_rad_s.allFinite()) {
    ++counters_.imu_invalid;
    return;
  }
  if (have_raw_ && !(raw.t_s > last_raw_t_s_)) {
    ++counters_.imu_non_increasing;
    return;
  }
  have_raw_ = true;
  last_raw_t_s_ = raw.t_s;
  ImuSample s;
  if (prefilter_->push(raw, s)) push_filtered(s);
}

void Navigator::push_filtered(const ImuSample& s) {
  if (!imu_.empty() && !(s.t_s > imu_.back().t_s)) {
    ++counters_.imu_non_increasing;
    return;
  }
  if (imu_.full()) {  // horizon longer than the buffer: process the oldest now
    process(imu_.front());
    imu_.pop();
  }
  imu_.push(s);
  while (!imu_.empty() && imu_.front().t_s <= s.t_s - cfg_.horizon_s) {
    process(imu_.front());
    imu_.pop();
  }
}

void Navigator::push_gnss(const GnssObservation& z) {
  if (!gnss_.push(z)) ++counters_.gnss_overflow;
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
  if (dt > cfg_.max_imu_gap_s) ++counters_.imu_gaps;

  if (!aligned()) {
    alignment_.add_imu(s, dt);
    AlignmentResult res;
    const double latency = filter_.gps_latency_s();
    while (!gnss_.empty() && gnss_.front().arrival_s - latency <= s.t_s) {
      const GnssObservation z = gnss_.front();
      gnss_.pop();
      if (alignment_.add_gnss(z, s.t_s, res)) {
        nav_ = res.nav;
        last_position_accepted_t_ = s.t_s;
        filter_.seed_gyro_bias(res.gyro_bias_rad_s, res.gyro_bias_sigma_rad_s);
        filter_.set_reference_temperature(res.temp_ref_degC);
        break;
      }
    }
    prev_ = s;
    if (aligned()) emit();
    return;
  }

  const BodyRates r0 = filter_.compensate(prev_);
  const BodyRates r1 = filter_.compensate(s);
  Eigen::Vector3d f_n;
  const Eigen::Vector3d v_before = nav_.v_n_m_s;
  strapdown_step(nav_, r0, r1, dt, f_n);
  nav_.t_s = s.t_s;
  accel_n_ = (nav_.v_n_m_s - v_before) / dt;

  PredictInput in;
  in.nav = &nav_;
  in.specific_force_b_m_s2 = 0.5 * (r0.specific_force_b_m_s2 + r1.specific_force_b_m_s2);
  in.angular_rate_b_rad_s = 0.5 * (r0.angular_rate_b_rad_s + r1.angular_rate_b_rad_s);
  in.specific_force_n_m_s2 = f_n;
  in.temp_delta_degC = s.has_temp ? s.temp_degC - filter_.reference_temperature() : 0.0;
  in.dt_s = dt;
  predict_.add(in);
  if (predict_.pending_s() >= cfg_.covariance_period_s - 1e-9) predict_.flush(filter_);

  fuse_due_gnss(s.t_s, dt, r1);
  fuse_magnetometer(s);
  prev_ = s;
  emit();
}

void Navigator::fuse_due_gnss(double t_now, double dt, const BodyRates& now) {
  while (!gnss_.empty()) {
    const GnssObservation& z = gnss_.front();
    const double t_meas = z.arrival_s - filter_.gps_latency_s();
    if (t_meas > t_now) break;
    const double dt_back = t_now - t_meas;
    // Later than one IMU interval (plus slack for jitter) means the horizon missed it.
    if (dt_back > 1.5 * dt + 1e-3) {
      ++counters_.gnss_late;
      gnss_.pop();
      continue;
    }
    if (z.has_position) {
      Measurement m = gnss_position_measurement(filter_, nav_, dt_back, z, cfg_.gate_sigma);
      if (fuse(AidingSource::GnssPosition, m, t_meas)) {
        last_position_accepted_t_ = t_meas;
      } else if (t_meas - last_position_accepted_t_ > cfg_.reset_after_rejected_s) {
        // Rejected for too long: the filter, not the receiver, is wrong. Fuse
        // this epoch ungated (corrects velocity and attitude through the
        // correlations too); reset to it only if even that fails.
        ++counters_.gnss_resets;
        m.gate_sigma = kUngated;
        if (!fuse(AidingSource::GnssPosition, m, t_meas)) reset_to_gnss(z, dt_back);
        last_position_accepted_t_ = t_meas;
      }
    }
    if (z.has_velocity && cfg_.fuse_velocity) {
      fuse(AidingSource::GnssVelocity,
           gnss_velocity_measurement(filter_, nav_, now.angular_rate_b_rad_s, accel_n_, dt_back, z, cfg_.gate_sigma),
           t_meas);
    }
    gnss_.pop();
  }
}

void Navigator::fuse_magnetometer(const ImuSample& s) {
  if (!s.has_mag || !s.mag_b_uT.allFinite() || !filter_.layout().has(Effect::MagEarthField)) return;
  if (!mag_started_) {
    filter_.start_mag_field(nav_, s.mag_b_uT, cfg_.mag_sigma_uT);
    mag_started_ = true;
    last_mag_t_s_ = s.t_s;
    return;
  }
  if (s.t_s - last_mag_t_s_ < cfg_.mag_period_s - 1e-6) return;
  last_mag_t_s_ = s.t_s;
  fuse(AidingSource::Magnetometer, magnetometer_measurement(filter_, nav_, s.mag_b_uT, cfg_.mag_sigma_uT, cfg_.gate_sigma),
       s.t_s);
}

void Navigator::reset_to_gnss(const GnssObservation& z, double dt_back) {
  const StateLayout& L = filter_.layout();
  const Eigen::Vector3d lever_n = nav_.C_nb() * filter_.lever_arm_b_m();
  const double rm = wgs84::meridian_radius_m(z.lat_rad) + z.h_m;
  const double rn = wgs84::transverse_radius_m(z.lat_rad) + z.h_m;
  // IMU position = antenna - C l, carried forward to the filter time.
  const Eigen::Vector3d offset = -lever_n + nav_.v_n_m_s * dt_back;
  nav_.lat_rad = z.lat_rad + offset.x() / rm;
  nav_.lon_rad = z.lon_rad + offset.y() / (rn * std::cos(z.lat_rad));
  nav_.h_m = z.h_m - offset.z();
  if (z.has_velocity) nav_.v_n_m_s.head<2>() = z.v_ne_m_s;
  StateMat& P = filter_.P();
  auto reset_block = [&P](Eigen::Index start, const Eigen::Vector3d& sigma) {
    P.middleRows(start, 3).setZero();
    P.middleCols(start, 3).setZero();
    for (Eigen::Index i = 0; i < 3; ++i) P(start + i, start + i) = sigma(i) * sigma(i);
  };
  reset_block(L.pos.start, z.sigma_ned_m);
  if (z.has_velocity) reset_block(L.vel.start, cfg_.initial.vel_ned_m_s);
}

bool Navigator::fuse(AidingSource src, const Measurement& m, double t_meas) {
  predict_.flush(filter_);  // P to the time of this update
  InnovationRecord rec;
  rec.t_s = t_meas;
  rec.source = src;
  rec.result = fuse_measurement(filter_.P(), dx_, m);
  const auto i = static_cast<std::size_t>(src);
  if (rec.result.accepted) {
    ++counters_.accepted[i];
    filter_.feedback(dx_, nav_);
  } else {
    ++counters_.rejected[i];
  }
  if (observer_) observer_->on_innovation(rec);
  return rec.result.accepted;
}

void Navigator::emit() {
  if (!observer_) return;
  // P is the last prediction's: at most covariance_period_s old.
  out_.nav = nav_;
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
