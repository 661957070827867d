// Vehicle constraints: zero velocity while still, and a ground vehicle's
// non-holonomic constraint while it moves.
#include "estimator/nav/navigator.hpp"

#include <algorithm>
#include <cmath>

#include "estimator/ekf/aiding/zero_velocity/zero_velocity.hpp"

namespace sinu::est {

void Navigator::fuse_vehicle_constraints(const ImuSample& s, const BodyRates& now) {
  // Still: the IMU says so, and so does the receiver's speed when it is
  // recent; without it, the INS's own speed within 3 sigma of standing (a
  // steady straight leg at 45 m/s in a GNSS gap looks as quiet to the IMU).
  const bool gnss_recent = s.t_s - last_gnss_pos_t_s_ < cfg_.gnss_timeout_s;
  const Eigen::Index v = filter_.layout().vel.start;
  const double sigma_vh = std::sqrt(std::max(filter_.P()(v, v), filter_.P()(v + 1, v + 1)));
  const bool slow = gnss_recent ? last_gnss_speed_m_s_ < cfg_.still_max_gnss_speed_m_s
                                : nav_.v_n_m_s.head<2>().norm() < cfg_.still_max_gnss_speed_m_s + 3.0 * sigma_vh;
  const bool still = stillness_.still() && slow;
  still_now_ = still;
  const bool zupt = ground_vehicle() || cfg_.zero_velocity_in_air;
  if (zupt && still && s.t_s - last_zupt_t_s_ >= cfg_.zero_velocity_period_s - 1e-6) {
    last_zupt_t_s_ = s.t_s;
    fuse(AidingSource::ZeroVelocity,
         zero_velocity_measurement(filter_, nav_, cfg_.zero_velocity_sigma_m_s, cfg_.gate_sigma), s.t_s);
  }
  if (!ground_vehicle() || still) return;
  if (nav_.v_n_m_s.head<2>().norm() < cfg_.nonholonomic_min_speed_m_s) return;
  if (s.t_s - last_nhc_t_s_ < cfg_.nonholonomic_period_s - 1e-6) return;
  last_nhc_t_s_ = s.t_s;
  const bool ok = fuse(AidingSource::Nonholonomic,
                       nonholonomic_measurement(filter_, nav_, now.angular_rate_b_rad_s, cfg_.nonholonomic,
                                                cfg_.gate_sigma, nhc_axes()),
                       s.t_s);
  if (cfg_.vehicle == VehicleKind::Auto) {
    vehicle_.on_constraint(s.t_s, ok);
    if (!ground_vehicle()) events_ |= nav_flag::kVehicleChanged;
  }
}

}  // namespace sinu::est
