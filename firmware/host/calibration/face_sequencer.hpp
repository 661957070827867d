#pragma once
// `sinu bench --positions N`: follows the board through the positions of a
// multi-position calibration as it is recorded. Works on 1-s means: a window
// is still when its specific force and rate scatter little and its mean
// points within a fraction of a degree of the previous window's. The first
// still window in an attitude not held yet starts a hold; `hold_s` of still
// windows there finish it; any motion before that restarts it. The position
// asked for next is the first of bench_positions.hpp's order not held yet;
// another new attitude is accepted too (the fit needs distinct attitudes,
// not a given order) and said to be so.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace sinu::calibration {

struct FaceSequencerConfig {
  double window_s = 1.0;
  double hold_s = 60.0;
  // A still board's 1-s windows: per-sample noise of a MEMS IMU is ~0.02 m/s^2
  // and ~0.002 rad/s (summed over axes); a hand holding it, a few times that.
  double accel_std_limit_m_s2 = 0.05;
  double gyro_std_limit_rad_s = 0.01;
  double tilt_limit_deg = 0.5;      // between consecutive 1-s means (the bench monitor's)
  double rate_change_limit_deg_s = 0.3;
  double same_attitude_deg = 20.0;  // closer than this to a held attitude: the same one
};

enum class FaceEvent { None, HoldStarted, Moved, Held, AlreadyHeld };

struct HeldFace {
  std::size_t asked = 0;         // the position asked for (bench_positions.hpp)
  std::string attitude;          // what was held (attitude_name)
  Eigen::Vector3d up_b = Eigen::Vector3d::Zero();
  double t_start_s = 0.0, t_end_s = 0.0;
};

class FaceSequencer {
 public:
  FaceSequencer(std::size_t positions, const FaceSequencerConfig& config);
  /// One sample; what happened when a window closed with it.
  FaceEvent add(double t_s, const std::array<double, 3>& specific_force, const std::array<double, 3>& rate_rad_s);
  bool finished() const { return faces_.size() >= positions_; }
  /// The position to ask for next (or being held).
  std::size_t next() const;
  bool holding() const { return holding_; }
  double held_s() const { return holding_ ? last_t_ - hold_start_s_ : 0.0; }
  /// The attitude of the current hold (or the last still one).
  const std::string& attitude() const { return attitude_; }
  const std::vector<HeldFace>& faces() const { return faces_; }
  const FaceSequencerConfig& config() const { return cfg_; }

 private:
  FaceEvent close_window(double t_s);
  bool is_held(const Eigen::Vector3d& up) const;

  std::size_t positions_;
  FaceSequencerConfig cfg_;
  bool started_ = false, have_prev_ = false, holding_ = false, said_already_ = false;
  double window_start_ = 0.0, n_ = 0.0, last_t_ = 0.0, hold_start_s_ = 0.0;
  Eigen::Vector3d f_sum_ = Eigen::Vector3d::Zero(), w_sum_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d f_sq_ = Eigen::Vector3d::Zero(), w_sq_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d prev_f_ = Eigen::Vector3d::Zero(), prev_w_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d hold_f_ = Eigen::Vector3d::Zero();
  std::string attitude_;
  std::vector<HeldFace> faces_;
};

}  // namespace sinu::calibration
