#pragma once
// The horizontal position error ellipse (1 sigma) of a north/east covariance,
// as NMEA GST reports it: semi-axes and the direction of the major axis.
namespace sinu::board {

struct ErrorEllipse {
  double semi_major_m = 0.0;
  double semi_minor_m = 0.0;
  double orientation_deg = 0.0;  // of the semi-major axis, clockwise from true north, [0, 180)
};

/// From the 2x2 covariance [[var_n, cov_ne], [cov_ne, var_e]] [m^2]: the
/// square roots of its eigenvalues, and the eigenvector of the larger one.
/// A circle (no preferred direction) has orientation 0.
ErrorEllipse horizontal_error_ellipse(double var_n_m2, double cov_ne_m2, double var_e_m2);

}  // namespace sinu::board
