// GNSS aiding: position and velocity epochs fused at their time of validity,
// the noise they teach, and the checks and resets they drive (recovery,
// vertical, course).
#include "estimator/nav/navigator.hpp"

#include <algorithm>
#include <cmath>

#include "estimator/ekf/aiding/gnss_position/gnss_position.hpp"
#include "estimator/ekf/aiding/gnss_velocity/gnss_velocity.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

NoiseAdapterConfig Navigator::white_scale_config() const {
  NoiseAdapterConfig white = cfg_.gnss_white_scale;  // at most all white
  white.max_sigma = std::min(white.max_sigma, 1.0 / std::sqrt(1.0 - cfg_.tuning.gps_bias_variance_fraction));
  return white;
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
      // The solution knows its position far less well than the fix states
      // it (dead-reckoned through an outage, an IMU gap in motion): the
      // misfit is its own.
      const Eigen::Index p = filter_.layout().pos.start;
      const double fix_var = z.sigma_ned_m.head<2>().squaredNorm() / 2.0;
      if (std::max(filter_.P()(p, p), filter_.P()(p + 1, p + 1)) >
          cfg_.disturbed_position_sigmas * cfg_.disturbed_position_sigmas * fix_var) {
        disturbed(t_now);
      }
      last_gnss_pos_t_s_ = t_meas;
      bool ok = fuse(AidingSource::GnssPosition,
                     gnss_position_measurement(filter_, nav_, dt_back, z, cfg_.gate_sigma), t_meas);
      const double innovation_h = last_result_.innovation.head<2>().norm();
      if (!ok && !recovery_.is_jump(innovation_h, z.sigma_ned_m.head<2>().norm()) &&
          last_result_.innovation.head(last_result_.rows).allFinite()) {
        // A misfit too small to be a GNSS jump: the filter claimed more than it
        // knew. Widen the position by the misfit and fuse the epoch again
        // (no waiting for a reset while a centimetre receiver is ignored).
        // The misfit is the solution's: the receiver's correlated error does
        // not learn from it (disturbed).
        const Eigen::Vector3d y = last_result_.innovation;
        filter_.add_block_noise(filter_.layout().pos, y.cwiseAbs2().asDiagonal());
        ++counters_.position_inflations;
        disturbed(t_now);
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

void Navigator::recover(RecoveryAction action, const GnssObservation& z, double dt_back, double t_meas) {
  if (action == RecoveryAction::None) return;
  disturbed(t_meas);
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

}  // namespace sinu::est
