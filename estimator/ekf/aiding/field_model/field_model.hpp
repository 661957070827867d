#pragma once
// The World Magnetic Model's field strength and inclination (dip) as a
// measurement of the Earth-field state, fused once when the field states
// start (with the declination, aiding/declination, when the measured field is
// recognised). Why: the field state starts from the first sample, C_nb (m - h),
// so its error and the hard iron's are one 30-uT uncertainty that only a
// rotation separates; at rest every small attitude correction turns that
// direction and leaks it into what the magnetometer sees, and the two wander
// by tens of uT (and a soft iron learnt on top of them converges wrong). The
// model knows the Earth's field to ~0.2 uT; the strength's sigma also covers a
// magnetometer's scale error (up to ~10 %), the inclination's crustal
// anomalies and a scale that differs between axes (a few degrees). The
// inclination, not the down component: with the strength and the down
// component held, the field could still turn towards the vertical, its
// horizontal part going to zero at rest (the hard iron taking it), and the
// declination with it. Both are invariant to the heading, so an unrecognised
// field (a large hard iron) gets no heading from it: its offset goes to the
// hard iron.
// With the invariant field error e (state_layout.hpp), dF = e - [F x] phi, and
// a scalar h(F) with gradient g: y = h(F_hat) - h_model,
//   H_field = -g,  H_att = (g x F)^T (zero for the strength, g = F / |F|);
// the inclination I = atan2(F_d, H), H = |(F_n, F_e)|:
//   g = (-F_d F_n / H, -F_d F_e / H, H) / |F|^2.
#include <Eigen/Core>

#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ekf/measurement_update.hpp"

namespace sinu::est {

/// The soft iron's common scale, xx + yy + zz = 0 (with mag_soft_iron in the
/// layout): S = I + D scales the field S C_bn F, so a scale common to the
/// three diagonals is the field's strength again, and free it walked the
/// ridge (the independent simulator's soft-iron quadcopter: diagonals -0.28
/// each with the field at 69 uT against the model's 49.6; attitude 34.6 deg).
/// Held at zero the field's strength takes it (the magnetometer's scale).
/// H = -(1, 1, 1, 0, 0, 0) on the soft iron (its states are true - estimate).
Measurement soft_iron_scale_measurement(const ErrorStateFilter& filter, double sigma, double gate_sigma);

/// Needs the mag_earth_field states (Effect::MagEarthField) in the layout.
/// model_field_n_uT: the model's field at the site, NED [uT].
Measurement field_model_measurement(const ErrorStateFilter& filter, const Eigen::Vector3d& model_field_n_uT,
                                    double strength_sigma_uT, double inclination_sigma_rad, double gate_sigma);

}  // namespace sinu::est
