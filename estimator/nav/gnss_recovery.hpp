#pragma once
// When to give up on the filter and reset it to GNSS (PX4 EKF2 resets to
// GNSS after its innovations have failed for a few seconds). The test
// ratios decide who is wrong:
//   - position rejected by a jump (more than jump_min_m and jump_sigmas of the
//     fix's own sigma) while the GNSS velocity is accepted: the INS moves as
//     the receiver says, so the receiver's position has jumped (multipath, a
//     spoofing step): hold the solution and flag the GNSS as suspect; only
//     after `jump_hold_s` does a persistent offset win (a datum change). A
//     smaller misfit is the filter claiming more than it knows (an RTK fix
//     against an INS with unmodelled centimetres): reset as below;
//   - position rejected and velocity rejected (or absent): the filter is
//     wrong (clipping, a gap, a bad start): reset position and velocity after
//     `reset_after_s`, and the yaw too if the velocity has been rejected while
//     moving;
//   - velocity alone rejected for `reset_after_s`: reset it (and the yaw when
//     moving).
// A solution whose position and velocity have both been rejected for
// `lost_after_s`, while fixes keep arriving, is lost until the next accepted
// position (no fixes at all is an outage, not a loss).
#include <algorithm>
#include <cstdint>

namespace sinu::est {

struct RecoveryConfig {
  double reset_after_s = 5.0;
  double jump_hold_s = 30.0;
  double lost_after_s = 10.0;
  double velocity_agrees_within_s = 1.0;  // a velocity accepted this recently vouches for the INS
  double jump_min_m = 1.0;
  double jump_sigmas = 10.0;
  double yaw_reset_min_speed_m_s = 5.0;   // below it the velocity says nothing of the heading
};

enum class RecoveryAction : std::uint8_t { None, ResetPosition, ResetVelocity, ResetVelocityAndYaw };

class GnssRecovery {
 public:
  void configure(const RecoveryConfig& cfg) {
    cfg_ = cfg;
    restart(0.0);
  }
  /// The filter was (re)started or reset at t: every timer starts afresh.
  void restart(double t_s);
  /// Outcome of the position update of an epoch valid at t: its horizontal
  /// innovation [m] and the fix's own horizontal sigma [m].
  RecoveryAction on_position(double t_s, bool accepted, double innovation_h_m, double fix_sigma_h_m);
  /// An epoch was found at t (the filter time) that could not be fused at all (later than the
  /// delayed horizon): for the loss detector, a rejection that says nothing
  /// of who is wrong.
  void on_unusable(double t_s);
  /// Outcome of the velocity update of an epoch valid at t; speed over ground.
  RecoveryAction on_velocity(double t_s, bool accepted, double speed_m_s);
  bool lost(double t_s) const;
  bool gnss_suspect(double t_s) const;
  /// A horizontal misfit large enough to be the receiver's jump, not the filter's error.
  bool is_jump(double innovation_h_m, double fix_sigma_h_m) const {
    return innovation_h_m > std::max(cfg_.jump_min_m, cfg_.jump_sigmas * fix_sigma_h_m);
  }
  /// A GNSS velocity was accepted recently: the INS (and its attitude) moves as the receiver says.
  bool velocity_agrees(double t_s) const { return t_s - last_vel_accept_s_ <= cfg_.velocity_agrees_within_s; }

 private:

  RecoveryConfig cfg_;
  double last_pos_accept_s_ = 0.0, last_vel_accept_s_ = -1e300;
  double pos_reject_since_s_ = 0.0, vel_reject_since_s_ = 0.0, last_pos_reject_s_ = -1e300;
  bool jump_ = false;
  bool pos_rejecting_ = false, vel_rejecting_ = false;
  bool moving_while_vel_rejected_ = false;
};

}  // namespace sinu::est
