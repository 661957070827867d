#pragma once
// The true state of the IMU at one instant and the ideal sensor outputs it
// implies on WGS-84 (Groves 2nd ed., eqs. 5.54 and 2.x, NED mechanisation):
//   f_b      = C_bn (dv_n/dt + (2 omega_ie_n + omega_en_n) x v_n - g_n)
//   omega_ib = omega_nb_b + C_bn (omega_ie_n + omega_en_n)
// with g_n = (0, 0, normal gravity(lat, h)) and omega_nb_b from the Euler
// ZYX angle rates of the attitude that the trajectory defines.
#include <Eigen/Core>

#include "firmware/host/sim/flight_controls.hpp"

namespace sinu::sim {

/// Integrated part of the trajectory state (everything else is a control).
struct NavState {
  double heading_rad = 0.0;  // yaw = ground track
  double lat_rad = 0.0, lon_rad = 0.0, h_m = 0.0;
};

struct TrueMotion {
  double t_s = 0.0;
  double lat_rad = 0.0, lon_rad = 0.0, h_m = 0.0;
  Eigen::Vector3d v_n_m_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_n_m_s2 = Eigen::Vector3d::Zero();  // dv_n/dt
  double roll_rad = 0.0, pitch_rad = 0.0, yaw_rad = 0.0;
  Eigen::Matrix3d C_nb = Eigen::Matrix3d::Identity();       // body -> NED
  Eigen::Vector3d omega_nb_b_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d omega_en_n_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_b_m_s2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d omega_ib_b_rad_s = Eigen::Vector3d::Zero();
};

/// A coordinated turn's heading rate at this bank and speed: g tan(bank) / V.
double coordinated_turn_rate_rad_s(double bank_rad, double speed_m_s);
/// The controls' heading rate: the coordinated turn's, 0 below c.min_turn_speed_m_s.
double heading_rate_rad_s(const ControlValues& c);
/// NED velocity of ground speed V along heading psi at flight-path angle gamma.
Eigen::Vector3d velocity_ned(const ControlValues& c, double heading_rad);
/// Rotation body FRD -> NED from Euler ZYX angles.
Eigen::Matrix3d C_nb_from_euler(double roll_rad, double pitch_rad, double yaw_rad);

/// Everything at time t from the controls and the integrated state.
TrueMotion evaluate_motion(double t_s, const ControlValues& c, const NavState& s);

}  // namespace sinu::sim
