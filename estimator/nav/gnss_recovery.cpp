#include "estimator/nav/gnss_recovery.hpp"

#include <algorithm>

namespace sinu::est {

void GnssRecovery::restart(double t_s) {
  last_pos_accept_s_ = t_s;
  pos_rejecting_ = vel_rejecting_ = false;
  moving_while_vel_rejected_ = false;
}

RecoveryAction GnssRecovery::on_position(double t_s, bool accepted, double innovation_h_m, double fix_sigma_h_m) {
  if (accepted) {
    last_pos_accept_s_ = t_s;
    pos_rejecting_ = false;
    return RecoveryAction::None;
  }
  last_pos_reject_s_ = t_s;
  jump_ = is_jump(innovation_h_m, fix_sigma_h_m);
  if (!pos_rejecting_) {
    pos_rejecting_ = true;
    pos_reject_since_s_ = t_s;
  }
  const double rejected_for = t_s - pos_reject_since_s_;
  if (rejected_for < cfg_.reset_after_s) return RecoveryAction::None;
  if (jump_ && velocity_agrees(t_s) && rejected_for < cfg_.jump_hold_s) return RecoveryAction::None;  // the GNSS jumped
  pos_rejecting_ = false;
  last_pos_accept_s_ = t_s;
  return RecoveryAction::ResetPosition;
}

void GnssRecovery::on_unusable(double t_s) {
  last_pos_reject_s_ = t_s;
  jump_ = false;
  if (!pos_rejecting_) {
    pos_rejecting_ = true;
    pos_reject_since_s_ = t_s;
  }
}

RecoveryAction GnssRecovery::on_velocity(double t_s, bool accepted, double speed_m_s) {
  if (accepted) {
    last_vel_accept_s_ = t_s;
    vel_rejecting_ = false;
    moving_while_vel_rejected_ = false;
    return RecoveryAction::None;
  }
  if (!vel_rejecting_) {
    vel_rejecting_ = true;
    vel_reject_since_s_ = t_s;
  }
  if (speed_m_s >= cfg_.yaw_reset_min_speed_m_s) moving_while_vel_rejected_ = true;
  if (t_s - vel_reject_since_s_ < cfg_.reset_after_s) return RecoveryAction::None;
  vel_rejecting_ = false;
  const bool yaw = moving_while_vel_rejected_;
  moving_while_vel_rejected_ = false;
  return yaw ? RecoveryAction::ResetVelocityAndYaw : RecoveryAction::ResetVelocity;
}

bool GnssRecovery::lost(double t_s) const {
  const bool fixes_arriving = t_s - last_pos_reject_s_ <= 1.0;
  return pos_rejecting_ && fixes_arriving && t_s - pos_reject_since_s_ >= cfg_.lost_after_s && !velocity_agrees(t_s);
}

bool GnssRecovery::gnss_suspect(double t_s) const {
  return pos_rejecting_ && jump_ && velocity_agrees(t_s) && t_s - last_pos_reject_s_ <= 1.0;
}

}  // namespace sinu::est
