#include "firmware/host/sim/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "estimator/earth/wgs84.hpp"

namespace sinu::sim {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMinPrimitive_s = 0.5;  // guards against a zero-length plan
}  // namespace

Site draw_site(Rng& rng) {
  Site s;
  s.lat_rad = rng.uniform(-60.0, 60.0) * kDeg;
  s.lon_rad = rng.uniform(-180.0, 180.0) * kDeg;
  s.ground_h_m = rng.uniform(0.0, 600.0);
  s.heading_rad = rng.uniform(-180.0, 180.0) * kDeg;
  return s;
}

Trajectory::Trajectory(const Site& site, double t0_s, double end_s, double substep_s, Rng& rng, Airframe airframe)
    : site_(site), t0_s_(t0_s), end_s_(end_s), substep_s_(substep_s), planner_(rng, airframe) {
  state_ = {site.heading_rad, site.lat_rad, site.lon_rad, site.ground_h_m};
  controls_.min_turn_speed_m_s = min_turn_speed_m_s(airframe);
  controls_.speed.hold(0.0);
  controls_.gamma.hold(0.0);
  controls_.bank.hold(0.0);
  controls_.alpha.hold(0.0);
  primitive_end_s_ = t0_s;
  begin_primitive_if_due();
}

void Trajectory::begin_primitive_if_due() {
  const double t = time();
  while (t >= primitive_end_s_) {
    primitive_ = planner_.next({t, end_s_, state_.h_m - site_.ground_h_m});
    controls_.speed.start(t, primitive_.ramp_s, primitive_.speed_m_s);
    controls_.gamma.start(t, primitive_.ramp_s, primitive_.gamma_rad);
    controls_.bank.start(t, primitive_.ramp_s, primitive_.bank_rad);
    controls_.alpha.start(t, primitive_.ramp_s, primitive_.alpha_rad);
    primitive_end_s_ = t + std::max(kMinPrimitive_s, primitive_.ramp_s + primitive_.hold_s);
  }
}

NavState Trajectory::derivative(double t, const NavState& s) const {
  namespace w = est::wgs84;
  const ControlValues c = controls_.at(t);
  const Eigen::Vector3d v = velocity_ned(c, s.heading_rad);
  return {heading_rate_rad_s(c), v.x() / (w::meridian_radius_m(s.lat_rad) + s.h_m),
          v.y() / ((w::transverse_radius_m(s.lat_rad) + s.h_m) * std::cos(s.lat_rad)), -v.z()};
}

NavState Trajectory::advanced(const NavState& s, double t, double dt) const {
  if (dt <= 0.0) return s;
  const NavState k1 = derivative(t, s);
  const NavState mid{s.heading_rad + 0.5 * dt * k1.heading_rad, s.lat_rad + 0.5 * dt * k1.lat_rad,
                     s.lon_rad + 0.5 * dt * k1.lon_rad, s.h_m + 0.5 * dt * k1.h_m};
  const NavState k2 = derivative(t + 0.5 * dt, mid);
  return {s.heading_rad + dt * k2.heading_rad, s.lat_rad + dt * k2.lat_rad, s.lon_rad + dt * k2.lon_rad,
          s.h_m + dt * k2.h_m};
}

TrueMotion Trajectory::motion() const { return evaluate_motion(time(), controls_.at(time()), state_); }

TrueMotion Trajectory::motion_at(double t) const {
  const NavState s = advanced(state_, time(), t - time());
  return evaluate_motion(t, controls_.at(t), s);
}

void Trajectory::step() {
  state_ = advanced(state_, time(), substep_s_);
  state_.heading_rad = std::remainder(state_.heading_rad, 2.0 * std::numbers::pi);
  ++index_;
  begin_primitive_if_due();
}

}  // namespace sinu::sim
