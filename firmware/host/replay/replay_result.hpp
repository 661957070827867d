#pragma once
// What a replay found, as values: the run (model, states, denoiser), the
// final effect and sensor-error estimates, the comparison with truth, the
// innovation statistics, the health and every counter. `sinu replay` prints
// it and writes summary.json from it; `sinu diagnose` compares candidate
// models with it. The streams (each solution, each innovation) go to
// ReplayListeners while the replay runs.
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "estimator/nav/navigator.hpp"
#include "firmware/host/replay/nav_metrics.hpp"
#include "firmware/host/replay/replay_source.hpp"

namespace sinu::replay {

struct EffectEstimate {
  est::Effect effect{};
  std::vector<double> estimate, sigma;  // per component
};

/// What the flight excited: the range of each IMU axis, the temperature, and
/// whether there was a magnetometer (diagnose: which effects the data can test).
struct Excitation {
  // The specific force held for about a second (a one-pole low-pass, 1 s):
  // what a scale or a misalignment turns into a velocity error the GNSS can
  // see. Vibration integrates to nothing (the real drive's f_z spans 1.2 g
  // sample to sample, 0.08 g held for a second).
  static constexpr double kHoldTau_s = 1.0;
  Eigen::Vector3d f_min_m_s2 = Eigen::Vector3d::Constant(1e300), f_max_m_s2 = Eigen::Vector3d::Constant(-1e300);
  Eigen::Vector3d f_held_m_s2 = Eigen::Vector3d::Zero();
  double t_first_s = NAN, t_prev_s = NAN;
  Eigen::Vector3d w_min_rad_s = Eigen::Vector3d::Constant(1e300), w_max_rad_s = Eigen::Vector3d::Constant(-1e300);
  double temp_min_degC = 1e300, temp_max_degC = -1e300;
  std::uint64_t temp_samples = 0, mag_samples = 0;
  void add(const est::ImuSample& s);
  double temp_span_degC() const { return temp_samples ? temp_max_degC - temp_min_degC : 0.0; }
};

struct GnssFeedCounters {
  std::uint64_t epochs = 0, used = 0, dropped_outage = 0, dropped_period = 0;
  std::uint64_t without_height = 0;  // a horizontal fix with no height (RMC or GLL without GGA): fused north and
                                     // east once aligned (NavCounters::horizontal_fixes), never aligns the INS
  std::uint64_t observations = 0;          // epochs with a position or a velocity the unit can use
  double first_t_s = 0.0, last_t_s = 0.0;  // their validity times (when observations > 0)
};

/// What carried the unit: as configured, and with `auto` what the detector found.
struct VehicleOutcome {
  est::VehicleKind configured = est::VehicleKind::Auto;
  bool ground_at_end = false;       // the ground-vehicle constraints in use at the end
  est::VehicleGuess guess = est::VehicleGuess::Undecided;
  double detected_at_s = 0.0;       // valid when guess != Undecided and not restored
  bool restored = false;            // the guess came from the state file (a restart), not from this run
  double lateral_rms_m_s = 0.0, vertical_rms_m_s = 0.0, moving_s = 0.0;  // the detector's evidence
  double bank_per_g = 0.0;          // ... NaN while the turns varied too little to tell
  bool on_bracket = false;          // the detector found the unit turned or tilted on the vehicle:
  double unit_roll_deg = 0.0, unit_pitch_deg = 0.0, unit_yaw_deg = 0.0;  // its attitude on it (VehicleAxes)
};

enum class HealthStatus { Ok, Reset, LostAndRecovered, Lost, NotAligned };
const char* health_status_name(HealthStatus s);  // ok, reset, lost_and_recovered, lost, not_aligned

struct ReplayResult {
  std::string dataset;
  std::string denoiser = "none";  // "db4:3" or "none"
  double ar_rate_hz = 0.0;         // the AR states' step rate (AR only: the model rate when calib.json chose one)
  int states = 0;
  std::vector<EffectEstimate> effects;  // the effects switched on at the end, in layout order
  std::array<double, est::kSensorAxes> sensor_error{}, sensor_error_sigma{};
  std::uint64_t imu_samples = 0;
  Excitation excitation;
  double duration_s = 0.0;
  bool aligned = false;
  double aligned_at_s = 0.0;      // time of the first solution (valid when aligned)
  std::uint32_t last_flags = 0;   // nav_flag bits of the last solution
  bool has_truth = false;
  NavMetrics metrics;             // against truth.csv; NIS per source
  est::NavCounters counters;
  GnssFeedCounters gnss;
  VehicleOutcome vehicle;
  est::AlignmentResult alignment;  // how the first solution came about (valid when aligned)
  est::SensorScaleVerdict scale;   // the accelerometer and magnetometer against gravity and the Earth field
  SourceCounters source;
  double gnss_velocity_sigma_m_s = 0.0, mag_sigma_uT = 0.0;  // in use at the end (learnt or fixed)
  Eigen::Vector2d gnss_position_scale{1.0, 1.0};  // horizontal, vertical factor on unstated (no GST) sigmas
  Eigen::Vector2d gnss_white_scale{1.0, 1.0};     // horizontal, vertical factor on the white part of stated ones
  std::string note;               // what the user must know ("" if nothing): truncated recording, dropped rows

  HealthStatus health() const;
  /// Why nothing aligned, in a few words ("" when it did).
  std::string not_aligned_reason() const;
  /// Why the magnetometer was never used although the data has one ("" when it was, or there is none).
  std::string mag_refused_reason() const;
  /// RMSE against truth; NaN without truth points.
  double rmse_pos_h_m() const;
  double rmse_pos_v_m() const;
  double rmse_vel_m_s() const;
  double rmse_att_deg() const;
  // GNSS alone against truth, each fix at its time of validity: arrival
  // minus the latency the filter learnt (configured + gnss_latency_shift_s).
  double gnss_latency_shift_s = 0.0;
  double configured_gps_latency_s = 0.0;
  double gnss_retiming_s() const;  // the shift applied (none when truth.csv is the fixes themselves)
  double gnss_rmse_pos_h_m() const;
  /// The same at arrival minus the configured latency (what the fixes give a user who takes them as they come).
  double gnss_rmse_at_configured_pos_h_m() const;
  double gnss_rmse_pos_v_m() const;
  /// truth.csv holds the very fixes the filter was fed (an RTK log as its own
  /// reference): GNSS alone within 1 cm of it.
  bool truth_is_gnss_input() const { return gnss_rmse_at_configured_pos_h_m() < 0.01; }
  /// RMS over the scored outages of the maximum horizontal drift; NaN if none was scored.
  double outage_drift_rms_m() const;
  const EffectEstimate* effect(est::Effect e) const;
};

}  // namespace sinu::replay
