#pragma once
// The site's magnetic declination as a measurement of the Earth-field state
// (PX4 EKF2 fuses the World Magnetic Model's declination likewise): the field
// the magnetometer model carries must point the model's way. A prior, fused
// once when the field states start, with the model's uncertainty; without it
// the field's direction is free, and in a hover, where GNSS says little of
// the heading, whatever pulls the heading turns the field with it.
// D = atan2(F_e, F_n) of the true field; y = D(F_hat) - D_model. With
// a = (-F_e, F_n, 0) / H^2 (H^2 = F_n^2 + F_e^2), dF = F - F_hat = e - [F x] phi
// (the invariant field error e, state_layout.hpp):
//   y = -a . dF = -a . e + phi . (a x F), so
//   H_field = -a,  H_att = (a x F)^T = (F_n F_d, F_e F_d, -H^2) / H^2
// (the yaw term -1: a declination of the field estimate is a heading relative
// to the magnetometer).
#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ekf/measurement_update.hpp"

namespace sinu::est {

/// Needs the mag_earth_field states (Effect::MagEarthField) in the layout.
Measurement declination_measurement(const ErrorStateFilter& filter, double declination_rad, double sigma_rad,
                                    double gate_sigma);

}  // namespace sinu::est
