#include "estimator/earth/geomagnetic_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "estimator/earth/wgs84.hpp"
#include "estimator/earth/wmm_coefficients.hpp"

namespace sinu::est::geomag {

namespace {

constexpr double kReferenceRadius_m = 6371200.0;  // the WMM's geomagnetic reference radius a
constexpr double kModelSpan_yr = 5.0;
constexpr int kN = kWmmDegree;

// Triangular tables indexed (n, m), 0 <= m <= n <= 12, on the stack.
using Table = std::array<double, (kN + 1) * (kN + 1)>;
constexpr std::size_t ix(int n, int m) { return static_cast<std::size_t>(n * (kN + 1) + m); }

const WmmCoefficients& model_for(double year) {
  if (year >= 2025.0) return kWmm2025;
  if (year >= 2020.0) return kWmm2020;
  return kWmm2015v2;
}

// Schmidt semi-normalised associated Legendre functions P_n^m(sin phi') and
// their derivatives d/dphi', phi' the geocentric latitude, s = sin phi',
// c = cos phi' >= 0. For m >= 1 also q = P_n^m / cos phi': P_n^m carries the
// factor cos^m phi', so q stays finite at the poles, where it gives the
// report's special case for the east component (only m = 1 survives there).
//   sectoral:  P_1^1 = c,  P_m^m = sqrt((2m-1)/(2m)) c P_{m-1}^{m-1}  (m >= 2)
//   along n:   P_n^m = ((2n-1) s P_{n-1}^m - sqrt((n-1)^2 - m^2) P_{n-2}^m) / sqrt(n^2 - m^2)
// and the same recursions differentiated (ds/dphi' = c, dc/dphi' = -s).
struct Legendre {
  Table p{}, dp{}, q{};
};

void schmidt_legendre(double s, double c, Legendre& L) {
  L.p[ix(0, 0)] = 1.0;
  for (int m = 0; m <= kN; ++m) {
    if (m >= 1) {  // sectoral seed (m, m) from (m-1, m-1)
      const double k = m == 1 ? 1.0 : std::sqrt((2.0 * m - 1.0) / (2.0 * m));
      const double p_prev = L.p[ix(m - 1, m - 1)], dp_prev = L.dp[ix(m - 1, m - 1)];
      L.q[ix(m, m)] = k * p_prev;
      L.p[ix(m, m)] = c * L.q[ix(m, m)];
      L.dp[ix(m, m)] = k * (c * dp_prev - s * p_prev);
    }
    for (int n = m + 1; n <= kN; ++n) {
      const double nm = n * n - m * m, n1m = (n - 1) * (n - 1) - m * m;
      const double a = (2.0 * n - 1.0) / std::sqrt(nm), b = std::sqrt(n1m / nm);
      const double p1 = L.p[ix(n - 1, m)], dp1 = L.dp[ix(n - 1, m)];
      const double p2 = n >= m + 2 ? L.p[ix(n - 2, m)] : 0.0;
      const double dp2 = n >= m + 2 ? L.dp[ix(n - 2, m)] : 0.0;
      const double q2 = n >= m + 2 ? L.q[ix(n - 2, m)] : 0.0;
      L.p[ix(n, m)] = a * s * p1 - b * p2;
      L.dp[ix(n, m)] = a * (c * p1 + s * dp1) - b * dp2;
      L.q[ix(n, m)] = a * s * L.q[ix(n - 1, m)] - b * q2;
    }
  }
}

}  // namespace

GeomagneticField geomagnetic_field(double lat_rad, double lon_rad, double h_ellipsoid_m, double year) {
  const WmmCoefficients& model = model_for(year);
  const double dt_yr = std::clamp(year - model.epoch_year, 0.0, kModelSpan_yr);

  // Geodetic -> geocentric spherical (radius r, latitude phi'); longitude is shared.
  const double rn = wgs84::transverse_radius_m(lat_rad);
  const double p = (rn + h_ellipsoid_m) * std::cos(lat_rad);
  const double z = (rn * (1.0 - wgs84::kE2) + h_ellipsoid_m) * std::sin(lat_rad);
  const double r = std::hypot(p, z);
  const double lat_c = std::atan2(z, p);

  Legendre L;
  schmidt_legendre(std::sin(lat_c), std::cos(lat_c), L);

  std::array<double, kN + 1> ratio_pow{};  // (a / r)^(n + 2)
  std::array<double, kN + 1> cos_ml{}, sin_ml{};
  ratio_pow[0] = (kReferenceRadius_m / r) * (kReferenceRadius_m / r);
  for (int k = 0; k <= kN; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (k > 0) ratio_pow[i] = ratio_pow[i - 1] * kReferenceRadius_m / r;
    cos_ml[i] = std::cos(k * lon_rad);
    sin_ml[i] = std::sin(k * lon_rad);
  }

  // Field in the geocentric spherical frame (north X', east Y', down Z') [nT]:
  //   X' = -sum (a/r)^(n+2) (g cos m lon + h sin m lon) dP_n^m/dphi'
  //   Y' =  sum (a/r)^(n+2) m (g sin m lon - h cos m lon) P_n^m / cos phi'
  //   Z' = -sum (n+1) (a/r)^(n+2) (g cos m lon + h sin m lon) P_n^m
  double x_s = 0.0, y_s = 0.0, z_s = 0.0;
  for (const GaussCoefficient& row : model.rows) {
    const double g = row.g_nT + dt_yr * row.g_dot_nT_yr;
    const double h = row.h_nT + dt_yr * row.h_dot_nT_yr;
    const auto m = static_cast<std::size_t>(row.m);
    const double w = ratio_pow[static_cast<std::size_t>(row.n)];
    const double cos_term = g * cos_ml[m] + h * sin_ml[m];
    x_s -= w * cos_term * L.dp[ix(row.n, row.m)];
    y_s += w * row.m * (g * sin_ml[m] - h * cos_ml[m]) * L.q[ix(row.n, row.m)];
    z_s -= w * (row.n + 1) * cos_term * L.p[ix(row.n, row.m)];
  }

  // Rotate about east by the difference of the latitudes back to geodetic NED.
  const double psi = lat_c - lat_rad;
  const Eigen::Vector3d b_nT{x_s * std::cos(psi) - z_s * std::sin(psi), y_s,
                             x_s * std::sin(psi) + z_s * std::cos(psi)};

  GeomagneticField f;
  f.b_n_uT = b_nT * 1e-3;
  f.horizontal_uT = std::hypot(f.b_n_uT.x(), f.b_n_uT.y());
  f.total_uT = f.b_n_uT.norm();
  f.declination_rad = std::atan2(f.b_n_uT.y(), f.b_n_uT.x());
  f.inclination_rad = std::atan2(f.b_n_uT.z(), f.horizontal_uT);
  f.in_validity = year >= kValidFromYear && year < kValidUntilYear;
  return f;
}

double decimal_year(int year, int month, int day, double seconds_of_day) {
  static constexpr std::array<int, 12> kDaysBefore{0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  const int mon = std::clamp(month, 1, 12);
  const int day_of_year = kDaysBefore[static_cast<std::size_t>(mon - 1)] + (leap && mon > 2 ? 1 : 0) + day;
  return year + (day_of_year - 1 + seconds_of_day / 86400.0) / (leap ? 366.0 : 365.0);
}

}  // namespace sinu::est::geomag
