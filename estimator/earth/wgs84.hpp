#pragma once
// WGS-84 ellipsoid, normal gravity and the rotation rates of the NED frame.
// References: NIMA TR8350.2 (WGS-84 constants), Groves, "Principles of GNSS,
// Inertial, and Multisensor Integrated Navigation Systems", 2nd ed., ch. 2.
#include <Eigen/Core>
#include <cmath>
#include <numbers>

namespace sinu::est::wgs84 {

inline constexpr double kA = 6378137.0;                 // semi-major axis [m]
inline constexpr double kF = 1.0 / 298.257223563;       // flattening
inline constexpr double kB = kA * (1.0 - kF);           // semi-minor axis [m]
inline constexpr double kE2 = kF * (2.0 - kF);          // first eccentricity squared
inline constexpr double kOmegaIe = 7.2921151467e-5;     // Earth rotation rate [rad/s]
inline constexpr double kGM = 3.986004418e14;           // gravitational constant [m^3/s^2]
inline constexpr double kGammaEquator = 9.7803253359;   // normal gravity at the equator [m/s^2]
inline constexpr double kSomiglianaK = 0.00193185265241;  // Somigliana's constant
inline constexpr double kStandardGravity = 9.80665;     // g0, the unit "g" (CGPM 1901) [m/s^2]

/// A longitude [rad] in [-pi, pi]: the antimeridian is no edge of the map.
inline double wrap_lon_rad(double lon_rad) { return std::remainder(lon_rad, 2.0 * std::numbers::pi); }
/// Longitude a - b [rad] the short way, in [-pi, pi] (179.9 E - 179.9 W = -0.2 deg).
inline double lon_difference_rad(double a_rad, double b_rad) { return wrap_lon_rad(a_rad - b_rad); }
/// The longitude a fraction f of the short way from a to b [rad].
inline double lon_between_rad(double a_rad, double b_rad, double f) {
  return wrap_lon_rad(a_rad + f * lon_difference_rad(b_rad, a_rad));
}

/// Meridian radius of curvature R_M (north-south) [m].
double meridian_radius_m(double lat_rad);
/// Prime-vertical (transverse) radius of curvature R_N (east-west) [m].
double transverse_radius_m(double lat_rad);

/// Normal gravity magnitude at geodetic latitude and ellipsoidal height [m/s^2]
/// (Somigliana at the surface, second-order free-air correction with height).
double normal_gravity_m_s2(double lat_rad, double h_m);

/// Earth rotation rate expressed in NED at latitude [rad/s].
Eigen::Vector3d omega_ie_n(double lat_rad);

/// Transport rate: rotation of NED w.r.t. the Earth from moving over it [rad/s].
Eigen::Vector3d omega_en_n(double lat_rad, double h_m, const Eigen::Vector3d& v_ned_m_s);

/// Geodetic (lat, lon [rad], h [m]) -> Earth-centred Earth-fixed [m].
Eigen::Vector3d geodetic_to_ecef(double lat_rad, double lon_rad, double h_m);

/// ECEF [m] -> geodetic (lat, lon [rad], h [m]); iterative, sub-millimetre.
Eigen::Vector3d ecef_to_geodetic(const Eigen::Vector3d& r_e_m);

/// Rotation matrix from NED at (lat, lon) to ECEF.
Eigen::Matrix3d C_en(double lat_rad, double lon_rad);

}  // namespace sinu::est::wgs84
