#include "estimator/ins/strapdown.hpp"

#include <cmath>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

namespace {

// Body-frame velocity increment in the frame of the interval's start for
// linear f(t) = f0 + d t and linear rate w(t) = w0 + b t:
// int_0^T f dt + int_0^T alpha(t) x f(t) dt, alpha(t) = w0 t + b t^2/2.
Eigen::Vector3d velocity_increment_b(const BodyRates& p, const BodyRates& c, double T) {
  const Eigen::Vector3d& w0 = p.angular_rate_b_rad_s;
  const Eigen::Vector3d b = (c.angular_rate_b_rad_s - w0) / T;
  const Eigen::Vector3d& f0 = p.specific_force_b_m_s2;
  const Eigen::Vector3d d = (c.specific_force_b_m_s2 - f0) / T;
  const double T2 = T * T, T3 = T2 * T, T4 = T3 * T;
  const Eigen::Vector3d integral_f = 0.5 * (f0 + c.specific_force_b_m_s2) * T;
  const Eigen::Vector3d rotation_sculling =
      w0.cross(f0) * (T2 / 2.0) + (w0.cross(d) + 0.5 * b.cross(f0)) * (T3 / 3.0) + b.cross(d) * (T4 / 8.0);
  return integral_f + rotation_sculling;
}

}  // namespace

void strapdown_step(NavState& nav, const BodyRates& prev, const BodyRates& cur, double T,
                    Eigen::Vector3d& mean_f_n) {
  const Eigen::Vector3d& w0 = prev.angular_rate_b_rad_s;
  const Eigen::Vector3d& w1 = cur.angular_rate_b_rad_s;
  const Eigen::Vector3d dtheta_b = 0.5 * (w0 + w1) * T + w0.cross(w1) * (T * T / 12.0);
  const Eigen::Vector3d dv_b = velocity_increment_b(prev, cur, T);

  // Mid-interval position, extrapolated with the old velocity.
  const double rm = wgs84::meridian_radius_m(nav.lat_rad) + nav.h_m;
  const Eigen::Vector3d v0 = nav.v_n_m_s;
  const double lat_mid = nav.lat_rad + 0.5 * T * v0.x() / rm;
  const double h_mid = nav.h_m - 0.5 * T * v0.z();

  const Eigen::Vector3d w_ie = wgs84::omega_ie_n(lat_mid);
  const Eigen::Vector3d w_en = wgs84::omega_en_n(lat_mid, h_mid, v0);
  const Eigen::Vector3d zeta = (w_ie + w_en) * T;  // NED frame rotation over the interval

  // Velocity: specific force into the mid-interval NED frame, then gravity and Coriolis.
  const Eigen::Matrix3d C_nb0 = nav.C_nb();
  const Eigen::Vector3d dv_sf_n = (Eigen::Matrix3d::Identity() - 0.5 * skew(zeta)) * C_nb0 * dv_b;
  const Eigen::Vector3d g_n(0.0, 0.0, wgs84::normal_gravity_m_s2(lat_mid, h_mid));
  // Coriolis with the velocity extrapolated to mid-interval (second order).
  const Eigen::Vector3d v_mid_guess = v0 + 0.5 * (dv_sf_n + (g_n - (2.0 * w_ie + w_en).cross(v0)) * T);
  const Eigen::Vector3d coriolis = (2.0 * w_ie + w_en).cross(v_mid_guess);
  const Eigen::Vector3d v1 = v0 + dv_sf_n + (g_n - coriolis) * T;
  mean_f_n = dv_sf_n / T;

  // Attitude: body rotation on the right, navigation-frame rotation on the left.
  nav.q_nb = (quat_from_rotation_vector(-zeta) * nav.q_nb * quat_from_rotation_vector(dtheta_b)).normalized();

  // Position: trapezoidal velocity; radii at mid-interval.
  const Eigen::Vector3d v_avg = 0.5 * (v0 + v1);
  const double rm_mid = wgs84::meridian_radius_m(lat_mid) + h_mid;
  const double rn_mid = wgs84::transverse_radius_m(lat_mid) + h_mid;
  const double lat_old = nav.lat_rad;
  nav.h_m -= v_avg.z() * T;
  nav.lat_rad += v_avg.x() * T / rm_mid;
  nav.lon_rad = wgs84::wrap_lon_rad(nav.lon_rad + v_avg.y() * T / (rn_mid * std::cos(0.5 * (lat_old + nav.lat_rad))));
  nav.v_n_m_s = v1;
  nav.t_s += T;
}

}  // namespace sinu::est
