#pragma once
// Magnetometer aiding, three axes (PX4 EKF2's "3-axis" fusion): the body
// field is the Earth field (a NED state) rotated into the body, through the
// magnetometer's axes (I - [theta x], optional states) and the soft iron
// S = I + D (optional states), plus the hard iron (a body state):
//   m_b = S (I - [theta x]) C_bn F_n + h_b (+ k (-f_z - g0), the motors'
//         field: effects/mag_motor_interference.hpp; C_bn tau earlier, a late
//         reading: effects/mag_latency.hpp) + noise  [uT]   (below: S = I,
//   theta = 0; with them H_field is premultiplied by A = S (I - [theta x]),
//   and each effect file gives its own rows: effects/mag_*.hpp).
// y = h(x_hat) - z. With phi (C_nb_hat = (I - [phi x]) C_nb), dF = F - F_hat,
// dh = h - h_hat:  y = -C_bn [F x] phi - C_bn dF - dh = -C_bn e - dh with the
// invariant field error e = dF + [F x] phi (state_layout.hpp), so
//   H_att = 0,  H_field = -C_bn,  H_hard_iron = -I.
// The magnetometer alone never tells the absolute attitude (the field is a
// state); through e's dynamics (e follows phi) it holds the heading on
// straight legs, once GNSS motion has tied the field to north.
#include "estimator/ekf/error_state_filter.hpp"
#include "estimator/ekf/measurement_update.hpp"
#include "estimator/ins/strapdown.hpp"

namespace sinu::est {

/// Needs the mag_earth_field states (Effect::MagEarthField) in the layout.
/// `now`: the IMU's specific force and rate, compensated, at the sample (the
/// motors' field follows the thrust, effects/mag_motor_interference.hpp; a
/// late reading saw the attitude the rate turned since, effects/mag_latency.hpp).
Measurement magnetometer_measurement(const ErrorStateFilter& filter, const NavState& nav,
                                     const Eigen::Vector3d& mag_b_uT, const BodyRates& now, double sigma_uT,
                                     double gate_sigma);

}  // namespace sinu::est
