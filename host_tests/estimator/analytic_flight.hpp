#pragma once
// Test-only reference trajectory, independent of the INS code: attitude and
// NED velocity are closed-form functions of time; position is integrated from
// them with RK4 at 1 ms; the IMU's specific force and angular rate are derived
// from the definitions (f_n = dv/dt - g + (2 w_ie + w_en) x v,
// w_ib = w_nb + C_bn (w_ie + w_en)) with central differences of the
// closed forms (step 1 ms: truncation error < 1e-9 of the signal).
// Profile: `rest_s` at rest (level within 0.02 rad), a 20 s run-up to cruise
// speed along the initial heading, then turns (coordinated, roll up to
// ~26 deg), climbs/descents and speed changes; every input is C1 so the
// sampled IMU has no kinks that no real sensor would show.
#include <vector>

#include "estimator/ekf/aiding/gnss_observation.hpp"
#include "estimator/ins/imu_sample.hpp"
#include "estimator/ins/nav_state.hpp"

namespace sinu::test {

struct FlightProfile {
  double t0_s = 1000.0;
  double lat0_deg = 40.0, lon0_deg = -105.0, h0_m = 1500.0;
  double yaw0_rad = 0.7;
  double rest_s = 30.0;
  double cruise_m_s = 40.0;
  bool stationary = false;  // at rest for ever (roll/pitch/yaw constant)
};

struct TruthSample {
  est::NavState nav;
  est::ImuSample imu;  // perfect sensor output at nav.t_s
};

class AnalyticFlight {
 public:
  explicit AnalyticFlight(const FlightProfile& p) : p_(p) {}
  /// Truth and perfect IMU samples at `rate_hz` (must divide 1000) for `duration_s`.
  std::vector<TruthSample> sample(double rate_hz, double duration_s) const;
  /// Perfect GNSS epochs (antenna = IMU + C_nb lever) every `every` truth samples.
  static std::vector<est::GnssObservation> gnss(const std::vector<TruthSample>& truth, std::size_t every,
                                                double latency_s, const Eigen::Vector3d& lever_b_m,
                                                double sigma_pos_m, double sigma_vel_m_s);

  Eigen::Vector3d velocity_n(double t) const;
  Eigen::Quaterniond attitude(double t) const;

 private:
  double speed(double t) const;
  double yaw(double t) const;
  double yaw_rate(double t) const;
  double flight_path(double t) const;
  FlightProfile p_;
};

/// Position error (computed - true) in NED metres.
Eigen::Vector3d position_error_ned(const est::NavState& est, const est::NavState& truth);
/// Attitude error angle [rad] between two attitudes.
double attitude_error_rad(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

}  // namespace sinu::test
