#include "firmware/board/outputs/error_ellipse.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sinu::board {

ErrorEllipse horizontal_error_ellipse(double var_n, double cov_ne, double var_e) {
  // Eigenvalues of a symmetric 2x2: mean +- radius of its Mohr circle.
  const double mean = 0.5 * (var_n + var_e);
  const double radius = std::hypot(0.5 * (var_n - var_e), cov_ne);
  ErrorEllipse e;
  e.semi_major_m = std::sqrt(std::max(mean + radius, 0.0));
  e.semi_minor_m = std::sqrt(std::max(mean - radius, 0.0));
  // Angle of the major axis from north (x) towards east (y): NED seen from
  // above, that is clockwise from true north, as NMEA's orientation.
  double deg = 0.5 * std::atan2(2.0 * cov_ne, var_n - var_e) * 180.0 / std::numbers::pi;
  if (deg < 0.0) deg += 180.0;
  e.orientation_deg = deg >= 180.0 ? 0.0 : deg;
  return e;
}

}  // namespace sinu::board
