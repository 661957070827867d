#pragma once
// The simulated GPS receiver. At each fix epoch (board time t_e, UTC time
// stamp utc(t_e)) it measures the antenna (IMU + C_nb lever_arm) at
// t_e - gps_latency (its velocity gps_velocity_latency earlier still), adds a
// position error (white + first-order GM, per NED axis) and a white velocity
// error, and emits GGA, RMC and GST sentences that arrive at
// t_e + base_latency + i * sentence_spacing.
#include <Eigen/Core>
#include <cstdint>
#include <deque>
#include <utility>

#include "firmware/host/dataset/nmea_log.hpp"
#include "firmware/host/sim/effects.hpp"
#include "firmware/host/sim/error_processes.hpp"
#include "firmware/host/sim/true_motion.hpp"

namespace sinu::sim {

struct GpsErrorModel {
  Eigen::Vector3d white_sigma_ned_m{0.4, 0.4, 0.8};
  Eigen::Vector3d gm_sigma_ned_m{1.2, 1.2, 2.5};
  double gm_tau_s = 120.0;
  Eigen::Vector3d velocity_sigma_ned_m_s{0.05, 0.05, 0.1};
  double base_latency_s = 0.045;      // fix epoch -> first sentence on the wire
  double sentence_spacing_s = 0.008;  // ~80 bytes at 115200 baud
  double corrupt_fraction = 0.002;    // of all sentences
  /// Total 1-sigma per NED axis, as GST reports it.
  Eigen::Vector3d sigma_ned_m() const;
};

/// Synthetic smooth geoid undulation N [m] (|N| < 45 m): MSL = h - N.
double geoid_separation_m(double lat_rad, double lon_rad);

/// UTC of the board clock: seconds since midnight of the start date =
/// board_s + utc_minus_board_s (past 86400 s the date advances).
struct UtcClock {
  double utc_minus_board_s = 0.0;
  int year = 2025, month = 6, day = 15;
};

class GpsReceiver {
 public:
  GpsReceiver(const GpsErrorModel& model, const Effects& effects, const UtcClock& clock, double fix_period_s,
              std::uint64_t seed);
  /// Antenna position/velocity truth for the IMU motion `m`.
  void antenna(const TrueMotion& m, double& lat_rad, double& lon_rad, double& h_m, Eigen::Vector3d& v_n) const;
  /// One epoch stamped `stamp_s` from the motion sampled at stamp_s - latency.
  bool fix(const TrueMotion& sampled, double stamp_s, dataset::NmeaLogWriter& out);
  double latency_s() const { return latency_s_; }
  /// The true motion at each IMU sample, for a velocity older than the fix
  /// (gps_velocity_latency): the antenna's velocity of the last second.
  void remember(const TrueMotion& m);
  std::uint64_t sentences() const { return sentences_; }
  std::uint64_t corrupted() const { return corrupted_; }

 private:
  bool emit(char* buf, std::size_t len, double arrival_s, dataset::NmeaLogWriter& out);
  Eigen::Vector3d velocity_before(const TrueMotion& m, const Eigen::Vector3d& v_now_n) const;

  GpsErrorModel model_;
  UtcClock clock_;
  Eigen::Vector3d lever_arm_b_m_;
  double latency_s_;
  double velocity_latency_s_;  // the velocity this much older than the position
  std::deque<std::pair<double, Eigen::Vector3d>> past_velocity_n_;  // (t, antenna v), last second
  Rng rng_, corrupt_rng_;
  GaussMarkov gm_[3];
  std::uint64_t sentences_ = 0, corrupted_ = 0;
};

}  // namespace sinu::sim
