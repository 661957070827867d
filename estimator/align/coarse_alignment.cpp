#include "estimator/align/coarse_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "estimator/align/field_heading_update.hpp"
#include "estimator/earth/geomagnetic_model.hpp"
#include "estimator/earth/wgs84.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

void CoarseAlignment::configure(const AlignmentConfig& cfg) {
  cfg_ = cfg;
  rest_.configure(cfg.rest);
  in_motion_.configure(cfg.in_motion);
  position_velocity_.configure(cfg.position_velocity);
  have_mag_ = false;
  tilt_since_s_ = -1.0;
  course_check_until_s_ = -1.0;
  status_ = AlignStatus::WaitingForRest;
  q_now_ = q_still_ = Eigen::Quaterniond::Identity();
  carried_s_ = carried_still_s_ = 0.0;
  have_still_ = false;
  still_windows_ = 0;
  field_ratio_ = NAN;
  dip_difference_rad_ = NAN;
}

namespace {
/// An in-motion tilt sigma good enough to align on (6 deg: the EKF, with this sigma, takes it from there).
constexpr double kGoodTilt = 0.1;
/// An attitude carried one sample by the gyros, less the rest's bias.
Eigen::Quaterniond carried(const Eigen::Quaterniond& q, const ImuSample& s, const RestEstimate& rest, double dt) {
  return (q * quat_from_rotation_vector((s.angular_rate_b_rad_s - rest.mean_rate_b_rad_s) * dt)).normalized();
}
/// The fix's date for the geomagnetic model; without one, the middle of its span.
double model_year(const GnssObservation& z) {
  return std::isfinite(z.decimal_year) ? z.decimal_year : 0.5 * (geomag::kValidFromYear + geomag::kValidUntilYear);
}
}  // namespace

void CoarseAlignment::add_imu(const ImuSample& s, double dt) {
  if (status_ == AlignStatus::Aligned) {
    if (checking_course()) in_motion_.add_imu(s, dt);
    return;
  }
  in_motion_.add_imu(s, dt);
  if (s.has_mag && s.mag_b_uT.allFinite()) {
    last_mag_b_uT_ = s.mag_b_uT;
    have_mag_ = true;
  }
  if (s.has_temp) last_temp_degC_ = s.temp_degC;
  rest_.add(s, dt);
  if (have_still_) {
    q_still_ = carried(q_still_, s, still_rest_, dt);
    carried_still_s_ += dt;
  }
  if (!rest_.has_estimate()) return;
  status_ = AlignStatus::Levelled;
  if (rest_.at_rest()) {  // still at rest: the levelling itself is the attitude
    q_now_ = rest_.estimate().q_level;
    carried_s_ = 0.0;
    return;
  }
  q_now_ = carried(q_now_, s, rest_.estimate(), dt);
  carried_s_ += dt;
}

void CoarseAlignment::check_rest(const GnssObservation& z) {
  if (!z.has_velocity || !rest_.has_estimate()) return;
  const double speed = z.v_ne_m_s.norm();
  // Differenced fixes are noisy: moving only beyond their noise.
  if (z.velocity_from_positions && speed >= cfg_.rest_contradicted_m_s &&
      speed < cfg_.rest_contradicted_m_s + 2.0 * z.sigma_vel_m_s)
    return;
  if (speed < cfg_.rest_contradicted_m_s) {
    if (!rest_.at_rest()) return;
    have_still_ = true;  // the rest as it is now, confirmed
    still_rest_ = rest_.estimate();
    still_windows_ = rest_.windows();
    q_still_ = q_now_;
    carried_still_s_ = 0.0;
    return;
  }
  // Moving: a window that began after the last still fix was no rest.
  if (have_still_) {
    if (rest_.windows() == still_windows_) return;
    rest_.restore(still_rest_);
    q_now_ = q_still_;
    carried_s_ = carried_still_s_;
    return;
  }
  if (rest_.at_rest() || rest_.windows() > 1) {
    rest_.forget();
    status_ = AlignStatus::WaitingForRest;
  }
}

bool CoarseAlignment::add_gnss(const GnssObservation& fix, double t_now, AlignmentResult& out) {
  if (status_ == AlignStatus::Aligned || !fix.has_position) return false;
  GnssObservation z = fix;
  position_velocity_.fill(z);
  check_rest(z);
  if (status_ == AlignStatus::WaitingForRest || !rest_.at_rest()) {
    // Moving (or never at rest): the in-motion alignment may finish first.
    if (align_in_motion(z, t_now, out)) return true;
    if (status_ == AlignStatus::WaitingForRest) return false;
  }
  const RestEstimate& r = rest_.estimate();
  // Magnetic heading: the field in the levelled (yaw 0) frame is Rz(-yaw) F_n,
  // whose horizontal angle is declination - yaw.
  if (cfg_.use_mag && r.has_mag) {
    const FieldDeclination d = declination_at(z);
    Eigen::Vector3d m_level;
    if (rest_field(r, d, m_level, out)) {
      use_declination(d, out);
      const double sigma = std::max(d.sigma_rad, field_heading_sigma(m_level, rest_tilt_sigma()));
      finish(z, t_now, d.rad - std::atan2(m_level.y(), m_level.x()), sigma, out);
      return true;
    }
  }
  if (!z.has_velocity || z.v_ne_m_s.norm() < cfg_.min_course_speed_m_s) return false;
  const double turn = std::atan2(z.v_ne_m_s.y(), z.v_ne_m_s.x()) - euler_from_quat(q_now_).z();
  out.heading_source = HeadingSource::GnssCourse;
  // A course from differenced fixes carries their noise and lag across the track too.
  const double sigma = z.velocity_from_positions
                           ? std::hypot(cfg_.course_heading_sigma_rad, z.sigma_vel_m_s / z.v_ne_m_s.norm())
                           : cfg_.course_heading_sigma_rad;
  finish(z, t_now, turn, sigma, out);
  return true;
}

CoarseAlignment::FieldDeclination CoarseAlignment::declination_at(const GnssObservation& z) const {
  if (cfg_.declination_known)
    return {cfg_.mag_declination_rad, cfg_.mag_heading_sigma_rad, 0.0, HeadingSource::MagnetometerGivenDeclination};
  if (!cfg_.use_geomagnetic_model)
    return {0.0, cfg_.mag_unknown_declination_sigma_rad, 0.0, HeadingSource::MagnetometerNoDeclination};
  // Without a date (GGA or VTG only, no RMC or ZDA): the model over its whole
  // span, its middle, the declination's drift to either end in the sigma
  // (0.1-0.2 deg a year at most sites: a few deg instead of 20).
  const bool dated = std::isfinite(z.decimal_year);
  const geomag::GeomagneticField f = geomag::geomagnetic_field(z.lat_rad, z.lon_rad, z.h_m, model_year(z));
  const double declination = f.declination_rad;
  double drift = 0.0;
  if (!dated) {
    for (const double end : {geomag::kValidFromYear, geomag::kValidUntilYear - 1e-3}) {
      const double d = geomag::geomagnetic_field(z.lat_rad, z.lon_rad, z.h_m, end).declination_rad;
      drift = std::max(drift, std::abs(std::remainder(d - declination, 2.0 * std::numbers::pi)));
    }
  }
  return {declination, std::hypot(cfg_.mag_heading_sigma_rad, drift), drift,
          dated ? HeadingSource::MagnetometerModelDeclination : HeadingSource::MagnetometerUndatedModel, f.total_uT,
          f.inclination_rad};
}

bool CoarseAlignment::field_recognised(const Eigen::Vector3d& m_level, const FieldDeclination& d) {
  if (!std::isfinite(d.model_total_uT)) return true;  // the model was not consulted
  // Not the Earth's field as the model knows it: an offset of tens of uT turns
  // the horizontal field by any angle, so no sigma makes its heading honest.
  const double dip = std::atan2(m_level.z(), m_level.head<2>().norm());
  field_ratio_ = m_level.norm() / d.model_total_uT;
  dip_difference_rad_ = dip - d.model_inclination_rad;
  return std::abs(field_ratio_ - 1.0) <= cfg_.geomag_max_field_ratio &&
         std::abs(dip_difference_rad_) <= cfg_.geomag_max_dip_rad;
}

bool CoarseAlignment::rest_field(const RestEstimate& r, const FieldDeclination& d, Eigen::Vector3d& m_level,
                                 AlignmentResult& out) {
  m_level = r.q_level * r.mean_mag_b_uT;
  // The saved iron first: learnt in flight with the GNSS, it holds the heading
  // a field read without it misses even where that one passes as the Earth's
  // (an independent simulator's quadcopters, restarted on the ground: 11-12
  // deg off for their last 100 s on fields 0.995x and 1.027x the model's).
  if (have_saved_iron_) {
    const Eigen::Vector3d saved = r.q_level * (saved_iron_A_ * r.mean_mag_b_uT + saved_iron_b_);
    saved_iron_refused_ = !field_recognised(saved, d);
    out.saved_iron_refused = saved_iron_refused_;
    if (!saved_iron_refused_) {
      m_level = saved;
      out.field_corrected_by_saved_iron = true;
      return true;
    }
  }
  return field_recognised(m_level, d);  // the refusal names the field as it is
}

void CoarseAlignment::use_declination(const FieldDeclination& d, AlignmentResult& out) const {
  out.heading_source = d.source;
  if (d.source == HeadingSource::MagnetometerNoDeclination) return;
  out.declination_rad = d.rad;
  out.declination_drift_rad = d.drift_rad;
}

void CoarseAlignment::record_field_check(const GnssObservation& z, AlignmentResult& out) const {
  out.field_ratio = field_ratio_;
  out.dip_difference_rad = dip_difference_rad_;
  if (cfg_.use_geomagnetic_model) {
    out.model_field_n_uT = geomag::geomagnetic_field(z.lat_rad, z.lon_rad, z.h_m, model_year(z)).b_n_uT;
  }
}

bool CoarseAlignment::align_in_motion(const GnssObservation& z, double t_now, AlignmentResult& out) {
  InMotionSolution s;
  if (!in_motion_.add_gnss(z, t_now, s)) return false;
  const bool tilt_good = s.att_sigma_rad.head<2>().maxCoeff() <= kGoodTilt;
  if (tilt_good && tilt_since_s_ < 0.0) tilt_since_s_ = t_now;
  if (s.yaw_observable) {
    if (!tilt_good) return false;
    out.heading_source = HeadingSource::InMotion;
    finish_in_motion(z, t_now, s, euler_from_quat(s.q_nb).z(), s.att_sigma_rad.z(), out);
    return true;
  }
  // The field's heading, and with it the tilt about a steady acceleration's axis.
  if (cfg_.use_mag && have_mag_ && with_field_heading(z, s, out) &&
      s.att_sigma_rad.head<2>().maxCoeff() <= kGoodTilt) {
    finish_in_motion(z, t_now, s, euler_from_quat(s.q_nb).z(), s.att_sigma_rad.z(), out);
    return true;
  }
  if (tilt_good && t_now - tilt_since_s_ >= cfg_.course_wait_s && z.has_velocity &&
      z.v_ne_m_s.norm() >= cfg_.min_course_speed_m_s) {
    out.heading_source = HeadingSource::GnssCourse;
    finish_in_motion(z, t_now, s, std::atan2(z.v_ne_m_s.y(), z.v_ne_m_s.x()), cfg_.course_heading_sigma_rad, out);
    return true;
  }
  return false;
}

bool CoarseAlignment::with_field_heading(const GnssObservation& z, InMotionSolution& s, AlignmentResult& out) {
  const FieldDeclination d = declination_at(z);
  const double horizontal_uT = (s.q_nb * last_mag_b_uT_).head<2>().norm();
  const double sigma = std::max(d.sigma_rad, std::atan2(cfg_.mag_residual_field_uT, horizontal_uT));
  InMotionSolution c = s;
  if (!update_with_field_heading(c.q_nb, c.att_cov_rad2, last_mag_b_uT_, d.rad, sigma)) return false;
  // The field is checked against the model at the updated tilt (in NED: levelled, its strength and dip).
  if (!field_recognised(c.q_nb * last_mag_b_uT_, d)) return false;
  c.att_sigma_rad = c.att_cov_rad2.diagonal().cwiseMax(0.0).cwiseSqrt();
  use_declination(d, out);
  s = c;
  return true;
}

void CoarseAlignment::finish_in_motion(const GnssObservation& z, double t_now, const InMotionSolution& s,
                                       double yaw, double yaw_sigma, AlignmentResult& out) {
  const double turn = yaw - euler_from_quat(s.q_nb).z();
  record_field_check(z, out);
  out.nav.q_nb = (Eigen::Quaterniond(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ())) * s.q_nb).normalized();
  out.at_rest = false;
  out.att_sigma_rad = {s.att_sigma_rad.x(), s.att_sigma_rad.y(), yaw_sigma};
  out.gyro_bias_rad_s = s.gyro_bias_rad_s;
  out.gyro_bias_sigma_rad_s = s.gyro_bias_sigma_rad_s.maxCoeff();
  out.nav.v_n_m_s = z.has_velocity ? Eigen::Vector3d(z.v_ne_m_s.x(), z.v_ne_m_s.y(), 0.0) : Eigen::Vector3d::Zero();
  out.nav.lat_rad = z.lat_rad;
  out.nav.lon_rad = z.lon_rad;
  out.nav.h_m = z.h_m;
  out.nav.t_s = t_now;
  // Horizontal velocity from the fix; vertical unknown (NMEA has none): a climb's few m/s.
  out.vel_sigma_m_s = {z.sigma_vel_m_s, z.sigma_vel_m_s, cfg_.climb_sigma_m_s};
  out.temp_ref_degC = last_temp_degC_;
  aligned(out, t_now);
}

double CoarseAlignment::rest_tilt_sigma() const {
  // The levelling's own noise plus what the gyros added since the rest.
  const double carried = rest_.estimate().mean_rate_sigma_rad_s * carried_s_;
  return std::sqrt(2e-3 * 2e-3 + carried * carried);
}

double CoarseAlignment::field_heading_sigma(const Eigen::Vector3d& m_level, double tilt_sigma) const {
  const double field_error_uT = std::hypot(cfg_.mag_residual_field_uT, std::abs(m_level.z()) * tilt_sigma);
  return std::atan2(field_error_uT, m_level.head<2>().norm());
}

void CoarseAlignment::finish(const GnssObservation& z, double t_now, double turn, double yaw_sigma,
                             AlignmentResult& out) {
  const RestEstimate& r = rest_.estimate();
  const Eigen::Quaterniond rot_down(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()));
  // The rest attitude now has a heading too: remove Earth rate from the turn-on bias.
  const Eigen::Quaterniond q_rest = rot_down * r.q_level;
  out.at_rest = true;
  out.rest_specific_force_b_m_s2 = r.mean_specific_force_b_m_s2;
  out.rest_specific_force_sigma_m_s2 = r.specific_force_sigma_m_s2;
  out.gyro_bias_sigma_rad_s = r.mean_rate_sigma_rad_s;
  out.gyro_bias_rad_s = r.mean_rate_b_rad_s - q_rest.conjugate() * wgs84::omega_ie_n(z.lat_rad);
  const double tilt = rest_tilt_sigma();
  out.att_sigma_rad = {tilt, tilt, yaw_sigma};
  // Levelled at rest and aligned on the next fix, or at the course speed a few s later.
  out.vel_sigma_m_s = Eigen::Vector3d::Constant(std::max(0.5, z.sigma_vel_m_s));
  // Moving since the rest (aligned on the course): it may be climbing, and NMEA has no vertical velocity.
  if (!rest_.at_rest()) out.vel_sigma_m_s.z() = cfg_.climb_sigma_m_s;
  out.nav.q_nb = (rot_down * q_now_).normalized();
  out.nav.v_n_m_s = z.has_velocity ? Eigen::Vector3d(z.v_ne_m_s.x(), z.v_ne_m_s.y(), 0.0) : Eigen::Vector3d::Zero();
  out.nav.lat_rad = z.lat_rad;
  out.nav.lon_rad = z.lon_rad;
  out.nav.h_m = z.h_m;
  out.nav.t_s = t_now;
  out.temp_ref_degC = r.temp_degC;
  record_field_check(z, out);
  aligned(out, t_now);
}

void CoarseAlignment::aligned(const AlignmentResult& out, double t_now) {
  status_ = AlignStatus::Aligned;
  course_check_until_s_ = out.heading_source == HeadingSource::GnssCourse ? t_now + cfg_.course_check_s : -1.0;
}

bool CoarseAlignment::check_course(const GnssObservation& fix, double t_now, double& yaw, double& sigma) {
  if (!checking_course() || !fix.has_position) return false;
  if (t_now > course_check_until_s_) {
    end_course_check();
    return false;
  }
  GnssObservation z = fix;
  position_velocity_.fill(z);
  InMotionSolution s;
  if (!in_motion_.add_gnss(z, t_now, s)) return false;
  if (s.att_sigma_rad.head<2>().maxCoeff() > kGoodTilt || s.att_sigma_rad.z() > cfg_.course_check_sigma_rad)
    return false;
  yaw = euler_from_quat(s.q_nb).z();
  sigma = s.att_sigma_rad.z();
  return true;
}

}  // namespace sinu::est
