#pragma once
// Test helper for the in-motion alignment: the analytic flight and a
// straight, level, constant-velocity trajectory; sensor errors added with a
// fixed seed; one run of InMotionAlignment over a time span, every solution
// scored against the truth.
#include <Eigen/Core>
#include <numbers>
#include <vector>

#include "estimator/align/in_motion_alignment.hpp"
#include "host_tests/estimator/analytic_flight.hpp"

namespace sinu::test {

inline constexpr double kDeg = std::numbers::pi / 180.0;
inline constexpr double kImuHz = 100.0;
inline constexpr std::size_t kGnssEvery = 10;  // 10 Hz GNSS
inline constexpr double kFlightStart = 1000.0;  // FlightProfile::t0_s: 30 s rest, 20 s run-up, then manoeuvres

struct Trajectory {
  std::vector<TruthSample> truth;
  std::vector<est::GnssObservation> gnss;  // gnss[j] is valid at truth[j * kGnssEvery]
};

/// The analytic flight, 100 Hz IMU, perfect 10 Hz GNSS (antenna at `lever`).
Trajectory make_flight(const Eigen::Vector3d& lever_b_m);
/// make_flight(0), built once.
const Trajectory& flight();
/// Straight, level flight along course 34 deg from 40 m/s, at a constant
/// acceleration along the track (0: constant velocity).
Trajectory straight_level(double duration_s, double accel_m_s2 = 0.0);

/// Sensor errors added in the test (default: perfect sensors).
struct Errors {
  double gnss_vel_sigma_m_s = 0.0, gnss_h_sigma_m = 0.0;  // white, per epoch
  double gyro_bias_rad_s = 0.0, accel_bias_m_s2 = 0.0;    // per axis, random sign
  double gyro_white_rad_s = 0.0, accel_white_m_s2 = 0.0;  // per sample
  unsigned seed = 1;
};

/// The brief's case: GNSS 0.1 m/s and 1 m, biases 0.2 deg/s and 0.05 m/s^2
/// per axis, a consumer MEMS's white noise at 100 Hz (SensorNoise defaults
/// 2.6e-4 rad/s/rtHz and 2.3e-3 m/s^2/rtHz, times sqrt(100 Hz)).
Errors realistic(unsigned seed);
/// The module configured with the statistics the test simulates.
est::InMotionAlignmentConfig matched(const Errors& e);
/// A calibrated unit (turn-on biases known to 0.02 deg/s and 0.02 m/s^2)
/// with the GNSS noise of the noisy cases (0.1 m/s white, 1 m), for the
/// perfect-sensor cases: the sigmas and the yaw flag then reflect the
/// geometry and the GNSS, not a poorly known gyro.
est::InMotionAlignmentConfig calibrated();

/// Attitude error phi in NED with C_hat = (I - [phi x]) C_true (the EKF's
/// att state): north/east from the body's down axis, down from the yaws.
Eigen::Vector3d attitude_error_ned(const Eigen::Quaterniond& est_q, const Eigen::Quaterniond& true_q);

/// Samples dropped from the streams: GNSS epochs / IMU samples in [from, to).
struct Gaps {
  double gnss_from_s = 0.0, gnss_to_s = 0.0;
  double imu_from_s = 0.0, imu_to_s = 0.0;
};

struct Outcome {
  int solutions = 0;
  double first_solution_s = -1.0, yaw_observable_s = -1.0;  // since the start; -1: never
  double max_tilt_err_rad = 0.0, max_yaw_err_rad = 0.0;      // yaw: while reported observable
  double max_tilt_ratio = 0.0, max_yaw_ratio = 0.0;          // |error| / sigma, see run()
  double final_tilt_sigma_rad = 0.0, final_yaw_sigma_rad = 0.0;
  double max_window_s = 0.0, max_gyro_bias_ratio = 0.0;
  int checked = 0, beyond_3_sigma = 0;          // solutions scored, and with an axis beyond 3 sigma
  int restarts = 0;                             // window_s went down
  double first_after_gap_s = -1.0, window_after_gap_s = -1.0;  // first solution after the GNSS gap
  // At 4, 9, ..., 29 s: tilt magnitude / RSS of the north and east sigmas
  // (their axes turn with a yaw error), and |yaw error| / yaw sigma.
  static constexpr int kSnaps = 6;
  Eigen::Matrix<double, kSnaps, 2> z = Eigen::Matrix<double, kSnaps, 2>::Zero();
};

/// Feeds [t_start, t_start + duration) of the trajectory (IMU and GNSS with
/// `err`, less `gaps`) into a fresh alignment and scores every solution
/// (see alignment_run.cpp for the ratios).
Outcome run(const Trajectory& tr, double t_start_s, double duration_s, const est::InMotionAlignmentConfig& cfg,
            const Errors& err, const Gaps& gaps = Gaps{});
void print(const char* name, const Outcome& o);

}  // namespace sinu::test
