#pragma once
// The still parts of a bench session, found from the data alone: statistics
// on short blocks, a block is still when its accelerometer and gyro variances
// are near the session's typical (median) block and its mean rate near the
// session's; runs of still blocks at least `min_duration_s` long, trimmed at
// both ends (the settling after a turn), are the segments. A session held in
// several attitudes (a six-position calibration) has one segment per hold;
// the turns between them are never still (the rate and the specific force's
// direction change within a block).
#include <Eigen/Core>
#include <cstddef>
#include <numbers>
#include <string>
#include <vector>

#include "firmware/host/calibration/static_session.hpp"

namespace sinu::calibration {

struct StillSegment {
  std::size_t input = 0;           // which session (--in) it is in
  std::size_t begin = 0, end = 0;  // sample indices [begin, end)
  double t_start_s = 0.0, t_end_s = 0.0;
  Eigen::Vector3d accel_mean_m_s2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_mean_rad_s = Eigen::Vector3d::Zero();
  double duration_s() const { return t_end_s - t_start_s; }
  /// The body's up direction: the specific force at rest points up.
  Eigen::Vector3d up_b() const { return accel_mean_m_s2.normalized(); }
};

struct StillDetectorConfig {
  double block_s = 0.5;
  // A block is still when the sum of its three axes' variances is below this
  // many times the session's median block (which is still: holds are most of
  // a session). The variance of 20 samples of white noise, summed over three
  // axes, scatters by ~20 % (57 degrees of freedom): 4x is never noise, while
  // a turn of a few seconds raises it by orders of magnitude.
  double variance_factor = 4.0;
  // Floors for a nearly noise-free session (quantisation-level noise):
  // below these nothing is motion [(m/s^2)^2, (rad/s)^2, summed over axes].
  double min_accel_variance = 1e-5;
  double min_gyro_variance = 1e-7;
  // A steady turn has little variance: its mean rate gives it away (the
  // bench monitor's 0.3 deg/s; Earth rate is 0.004 deg/s).
  double rate_limit_rad_s = 0.3 * std::numbers::pi / 180.0;
  double min_duration_s = 10.0;
  double trim_s = 1.0;
};

/// The still segments of `session` (its index `input` is recorded in each).
std::vector<StillSegment> find_still_segments(const StaticSession& session, std::size_t input,
                                              const StillDetectorConfig& config = {});

/// Groups segments by attitude: two segments whose up directions are within
/// `max_angle_rad` of each other are one attitude (a bench bumped by a few
/// degrees stays one). Returns the number of attitudes; `group` (optional)
/// gets each segment's attitude index, in order of first appearance.
inline constexpr double kSameAttitude_rad = 20.0 * std::numbers::pi / 180.0;
std::size_t count_attitudes(const std::vector<StillSegment>& segments, std::vector<std::size_t>* group = nullptr,
                            double max_angle_rad = kSameAttitude_rad);

/// The name of the bench position (bench_positions.hpp) nearest to `up_b`
/// within 20 deg ("+x up"), else the direction ("tilted (0.58, -0.58, 0.58) up").
std::string attitude_name(const Eigen::Vector3d& up_b);

/// Samples [begin, end) of `session` as a session of their own (the noise
/// models of a multi-position session are fitted on its longest hold).
StaticSession slice_session(const StaticSession& session, std::size_t begin, std::size_t end);

}  // namespace sinu::calibration
