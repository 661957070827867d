#include "firmware/host/sim/true_motion.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "estimator/earth/wgs84.hpp"

namespace sinu::sim {

namespace {
constexpr double kTurnGravity_m_s2 = 9.80665;  // defines the coordinated turn only
}  // namespace

double coordinated_turn_rate_rad_s(double bank_rad, double speed_m_s) {
  return kTurnGravity_m_s2 * std::tan(bank_rad) / speed_m_s;
}

double heading_rate_rad_s(const ControlValues& c) {
  if (c.speed_m_s < c.min_turn_speed_m_s) return 0.0;
  return coordinated_turn_rate_rad_s(c.bank_rad, c.speed_m_s);
}

Eigen::Vector3d velocity_ned(const ControlValues& c, double psi) {
  const double cg = std::cos(c.gamma_rad), sg = std::sin(c.gamma_rad);
  return c.speed_m_s * Eigen::Vector3d(cg * std::cos(psi), cg * std::sin(psi), -sg);
}

Eigen::Matrix3d C_nb_from_euler(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

TrueMotion evaluate_motion(double t_s, const ControlValues& c, const NavState& s) {
  namespace w = est::wgs84;
  TrueMotion m;
  m.t_s = t_s;
  m.lat_rad = s.lat_rad;
  m.lon_rad = s.lon_rad;
  m.h_m = s.h_m;

  const double psi = s.heading_rad, psi_dot = heading_rate_rad_s(c);
  const double V = c.speed_m_s, V_dot = c.speed_rate_m_s2;
  const double g = c.gamma_rad, g_dot = c.gamma_rate_rad_s;
  const double cg = std::cos(g), sg = std::sin(g), cp = std::cos(psi), sp = std::sin(psi);
  m.v_n_m_s = V * Eigen::Vector3d(cg * cp, cg * sp, -sg);
  m.accel_n_m_s2 = V_dot * Eigen::Vector3d(cg * cp, cg * sp, -sg) +
                   V * Eigen::Vector3d(-sg * g_dot * cp - cg * sp * psi_dot, -sg * g_dot * sp + cg * cp * psi_dot,
                                       -cg * g_dot);

  // Attitude: yaw along the track, pitch = flight path + angle of attack, roll = bank.
  m.roll_rad = c.bank_rad;
  m.pitch_rad = g + c.alpha_rad;
  m.yaw_rad = psi;
  m.C_nb = C_nb_from_euler(m.roll_rad, m.pitch_rad, m.yaw_rad);
  const double roll_dot = c.bank_rate_rad_s, pitch_dot = g_dot + c.alpha_rate_rad_s;
  const double sr = std::sin(m.roll_rad), cr = std::cos(m.roll_rad);
  const double st = std::sin(m.pitch_rad), ct = std::cos(m.pitch_rad);
  // Body rates from Euler ZYX angle rates.
  m.omega_nb_b_rad_s = {roll_dot - psi_dot * st, pitch_dot * cr + psi_dot * sr * ct,
                        -pitch_dot * sr + psi_dot * cr * ct};

  const Eigen::Vector3d omega_ie_n = w::omega_ie_n(s.lat_rad);
  m.omega_en_n_rad_s = w::omega_en_n(s.lat_rad, s.h_m, m.v_n_m_s);
  const Eigen::Vector3d g_n(0.0, 0.0, w::normal_gravity_m_s2(s.lat_rad, s.h_m));
  const Eigen::Matrix3d C_bn = m.C_nb.transpose();
  m.specific_force_b_m_s2 =
      C_bn * (m.accel_n_m_s2 + (2.0 * omega_ie_n + m.omega_en_n_rad_s).cross(m.v_n_m_s) - g_n);
  m.omega_ib_b_rad_s = m.omega_nb_b_rad_s + C_bn * (omega_ie_n + m.omega_en_n_rad_s);
  return m;
}

}  // namespace sinu::sim
