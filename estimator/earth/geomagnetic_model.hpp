#pragma once
// The Earth's main magnetic field from the World Magnetic Model (WMM): a
// degree-12 spherical-harmonic expansion of the core field with linear secular
// variation, evaluated at a geodetic WGS-84 position and a date.
// Reference: Chulliat et al., "The US/UK World Magnetic Model for 2025-2030:
// Technical Report", NOAA NCEI / BGS, 2024: its equations for the geodetic to
// geocentric conversion, the field synthesis and the rotation back to the
// ellipsoidal frame (the same as in the 2015 and 2020 reports).
// Coefficients: wmm_coefficients.hpp.
//
// Model by date: WMM2015 (its revision WMM2015v2) for years before 2020.0,
// WMM2020 for 2020.0 <= y < 2025.0, WMM2025 from 2025.0. Valid 2015.0 <= y < 2030.0;
// outside, the nearest model is evaluated with its time offset held to its own
// 5-year span and `in_validity` is false.
// Accuracy: the main field only. The WMM's stated global uncertainty is about
// 0.3-0.5 deg in declination (much larger near the magnetic poles, where the
// horizontal field is weak) and of the order of 100-150 nT in the components.
// Crustal anomalies (often several degrees of declination locally), the
// ionospheric and magnetospheric fields and the vehicle's own field are not in
// it. Valid from 1 km below the ellipsoid to about 850 km above it.
// Allocation-free; finite at the geographic poles.
#include <Eigen/Core>

namespace sinu::est::geomag {

inline constexpr double kValidFromYear = 2015.0;
inline constexpr double kValidUntilYear = 2030.0;  // exclusive

struct GeomagneticField {
  Eigen::Vector3d b_n_uT;   // north, east, down (X, Y, Z) [uT]
  double declination_rad;   // D: angle from true north to the horizontal field, east positive
  double inclination_rad;   // I: angle below the horizontal, down positive
  double total_uT;          // F = |b|
  double horizontal_uT;     // H = |(X, Y)|
  bool in_validity;         // decimal year inside [kValidFromYear, kValidUntilYear)
};

/// Main field at geodetic latitude, longitude [rad] and height above the
/// WGS-84 ellipsoid [m], on the date given as a decimal year (UTC).
GeomagneticField geomagnetic_field(double lat_rad, double lon_rad, double h_ellipsoid_m, double decimal_year);

/// UTC calendar date and time of day -> decimal year: year + (day of year - 1 +
/// seconds_of_day / 86400) / (365 or 366). Month 1-12, day 1-31.
double decimal_year(int year, int month, int day, double seconds_of_day);

}  // namespace sinu::est::geomag
