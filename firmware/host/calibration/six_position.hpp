#pragma once
// Multi-position (six-position) accelerometer calibration: in every still
// attitude the true specific force is gravity, so its magnitude is local
// gravity g. With the sensor model of the effects vocabulary
// (sim/effects.hpp, docs/simulation.md),
//   m = G f + b,   G = (I + diag s)(I + M),   M off-diagonal (M(i,j): axis i senses axis j),
// each still segment's mean m_k gives one equation
//   r_k = | G^-1 (m_k - b) | - g = 0,
// solved by weighted Levenberg-Marquardt from zero.
//
// What gravity can tell: any rotation R of the corrected triad keeps every
// magnitude, so G is known only up to G R^T: the antisymmetric part of M (a
// rotation of the accelerometer triad as a whole, 3 of the 12 unknowns) is
// not observable. It is fixed by taking M symmetric (the correction then
// turns the triad's mean axes by nothing: the polar decomposition's
// rotation is the identity), leaving 9 unknowns: b, s and the three
// symmetric misalignments. The six faces alone see M only at second order
// (|G e_i| = (1 + s_i)(1 + sum_j M_ji^2 / 2)): M is fitted when tilted
// positions excite every pair of axes, else b and s only (6 unknowns; s then
// carries that second-order term). A common factor of all three scales is
// not separable from g: g comes from the normal gravity formula at the given
// latitude and height, and its uncertainty is added to every scale's sigma.
//
// Gyro bias: each segment's mean rate minus the vertical part of Earth rate
// (Omega sin(lat) along the body's up direction, known from the calibrated
// accelerometer); the horizontal part (Omega cos(lat), its direction unknown
// without a heading) stays in the per-segment values and so in the sigma,
// which is their scatter over the segments.
#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "firmware/host/calibration/still_segments.hpp"

namespace sinu::calibration {

/// Local gravity from the normal gravity formula (estimator/earth/wgs84).
struct GravityModel {
  double latitude_deg = 45.0;
  double height_m = 0.0;
  bool latitude_given = false, height_given = false;
  // Unknown latitude: |g| spans 9.780..9.832 m/s^2 from equator to pole, a
  // uniform spread of 0.53 %, sigma 0.53 % / sqrt(12). Unknown height: 300 m
  // (1 sigma) at the free-air gradient 3.086e-6 /s^2.
  static constexpr double kUnknownHeightSigma_m = 300.0;
  double g_m_s2() const;
  /// 1-sigma relative uncertainty of g_m_s2() from what was not given.
  double relative_sigma() const;
};

/// What the fit uses of one still segment.
struct SegmentMean {
  Eigen::Vector3d accel_m_s2 = Eigen::Vector3d::Zero(), gyro_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_sigma_m_s2 = Eigen::Vector3d::Constant(1e-3);  // 1 sigma of the mean, per axis
};

struct SixPositionFit {
  // m = (I + diag s)(I + M) f + b   (the effects vocabulary's composition and units)
  Eigen::Vector3d accel_bias_m_s2 = Eigen::Vector3d::Zero(), accel_bias_sigma_m_s2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_scale_ppm = Eigen::Vector3d::Zero(), accel_scale_sigma_ppm = Eigen::Vector3d::Zero();
  Eigen::Matrix3d accel_misalign_rad = Eigen::Matrix3d::Zero();        // symmetric, zero diagonal
  Eigen::Matrix3d accel_misalign_sigma_rad = Eigen::Matrix3d::Zero();  // zero where not fitted
  bool misalign_fitted = false;
  Eigen::Vector3d gyro_bias_rad_s = Eigen::Vector3d::Zero(), gyro_bias_sigma_rad_s = Eigen::Vector3d::Zero();
  double gravity_m_s2 = 0.0, gravity_relative_sigma = 0.0;
  std::size_t segments = 0, parameters = 0, iterations = 0;
  std::size_t dof = 0;          // segments - parameters
  double chi2 = 0.0;            // sum of squared weighted residuals
  double residual_rms_m_s2 = 0.0;
  std::vector<double> residuals_m_s2;
  /// G^-1: f = correction() (m - b).
  Eigen::Matrix3d correction() const;
  /// G = (I + diag s)(I + M).
  Eigen::Matrix3d gain() const;
};

/// A multi-position calibration as calib.json's "six_position" holds it.
struct SixPositionCalibration {
  SixPositionFit fit;
  GravityModel gravity;
  std::vector<StillSegment> segments;   // used, in time order per input
  std::vector<SegmentMean> means;       // the same, as the fit saw them
  std::vector<std::string> datasets;    // per input (StillSegment::input)
  std::size_t attitudes = 0;
  // Per input: the span the noise models were fitted on (the whole session
  // when it was held in one attitude, else its longest still segment).
  struct Span {
    double t_start_s = 0.0, t_end_s = 0.0;
    bool whole = true;
  };
  std::vector<Span> noise_spans;
};

/// Whether the attitudes excite the misalignment: every pair of axes shares
/// gravity (|u_i u_j| >= 0.2, ~12 deg of tilt off a face) in some segment, and
/// there are more segments than the 9 unknowns.
bool misalignment_observable(const std::vector<SegmentMean>& segments);

/// Fits bias, scale (and misalignment when observable) and the gyro bias.
/// False with `why` when there are fewer than 6 segments or the fit fails.
bool fit_six_position(const std::vector<SegmentMean>& segments, const GravityModel& gravity, SixPositionFit& fit,
                      std::string& why);

/// Scale and symmetric misalignment equivalent to any gain G (the form the fit
/// reports, for comparing with a unit's true scale and full misalignment):
/// D (I + M_s)^2 D = G G^T with D = I + diag s, M_s symmetric, zero diagonal.
void symmetric_form(const Eigen::Matrix3d& G, Eigen::Vector3d& scale_ppm, Eigen::Matrix3d& misalign_sym_rad);

}  // namespace sinu::calibration
