// The restart: what the navigator saves for one (warm_state), what it takes
// back (warm_start), and what a power cycle or a battery swap may have
// changed, which only an alignment at rest checks: the saved iron (through
// the field) and the turn-on biases (through the rest).
#include "estimator/nav/navigator.hpp"

#include <algorithm>
#include <cmath>

namespace sinu::est {

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

void Navigator::keep_saved_biases(const Eigen::Vector3d& f_b, double sigma_along_m_s2) {
  const EffectPrior& gyro = warm_.effects[static_cast<std::size_t>(Effect::GyroBias)];
  const EffectPrior& accel = warm_.effects[static_cast<std::size_t>(Effect::AccelBias)];
  if (!gyro.given || !accel.given) return;
  constexpr double kSigmas = 3.0;
  // The gyro: seed_gyro_bias has just put the rest's measurement into the states.
  bool moved = false;
  for (Eigen::Index i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double sigma = std::hypot(filter_.effect_sigma(Effect::GyroBias, i), gyro.sigma[k]);
    moved |= !(std::abs(filter_.effect(Effect::GyroBias, i) - gyro.value[k]) <= kSigmas * sigma);
  }
  // The accelerometer along gravity, as the levelling will measure it.
  const Eigen::Vector3d u = f_b.normalized();
  double saved_along = 0.0, saved_var = 0.0;
  for (Eigen::Index i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    saved_along += u(i) * accel.value[k];
    saved_var += u(i) * u(i) * accel.sigma[k] * accel.sigma[k];
  }
  const double measured = filter_.accel_bias_along_gravity_at_rest(nav_, f_b);
  moved |= !(std::abs(measured - saved_along) <= kSigmas * std::sqrt(sigma_along_m_s2 * sigma_along_m_s2 + saved_var));
  alignment_result_.saved_biases = moved ? SavedBiases::Moved : SavedBiases::Kept;
  if (!moved) filter_.set_prior(Effect::AccelBias, accel);  // across gravity it levels the unit
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
  if (cfg_.vehicle == VehicleKind::Auto) {
    w.ground_vehicle = vehicle_.guess() == VehicleGuess::Ground;
    w.on_bracket = vehicle_.on_bracket();
    w.vehicle_axes = vehicle_axes_in_use(filter_, vehicle_.axes());
  }
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
    // Configured without it; or the unit's yaw on the vehicle, which the saved vehicle axes carry.
    if (!L.carries(effect) || effect == Effect::VehicleMount) {
      w.given = false;
      continue;
    }
    // At the alignment: by the field (offer_saved_iron), by the rest (keep_saved_biases).
    if (checked_by_the_field(effect) || checked_by_the_rest(effect)) continue;
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
  if (cfg_.vehicle == VehicleKind::Auto && warm_.ground_vehicle) vehicle_.restore(warm_.vehicle_axes, warm_.on_bracket);
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

}  // namespace sinu::est
