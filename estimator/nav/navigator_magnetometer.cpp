// Magnetometer aiding: the field states switched on by the first sample and
// their priors, each update, the heading check and the hard iron's re-anchor.
#include "estimator/nav/navigator.hpp"

#include <cmath>

#include "estimator/ekf/aiding/declination/declination.hpp"
#include "estimator/ekf/aiding/field_model/field_model.hpp"
#include "estimator/ekf/aiding/magnetometer/magnetometer.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

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

}  // namespace sinu::est
