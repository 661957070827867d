#pragma once
// Error-state EKF around the strapdown INS: covariance prediction, sensor
// compensation with the current estimates, and feedback of a correction.
// Measurements are built by the aiding sources (ekf/aiding/*) and fused with
// fuse_measurement(); the filter only owns the state and its bookkeeping.
#include "estimator/ekf/effect_tuning.hpp"
#include "estimator/ekf/measurement_update.hpp"
#include "estimator/ekf/sensor_error_model.hpp"
#include "estimator/ekf/sensor_noise.hpp"
#include "estimator/ekf/state_layout.hpp"
#include "estimator/ins/imu_sample.hpp"
#include "estimator/ins/nav_state.hpp"
#include "estimator/ins/rotation.hpp"
#include "estimator/ins/strapdown.hpp"

namespace sinu::est {

/// Initial navigation uncertainty (1 sigma).
struct NavUncertainty {
  Eigen::Vector3d pos_ned_m{3.0, 3.0, 5.0};
  Eigen::Vector3d vel_ned_m_s{0.5, 0.5, 0.5};
  Eigen::Vector3d att_rad{0.02, 0.02, 0.1};
};

/// What the INS saw over the last interval, for the error dynamics.
struct PredictInput {
  const NavState* nav = nullptr;              // after the strapdown step
  Eigen::Vector3d specific_force_b_m_s2;      // compensated, mid-interval
  Eigen::Vector3d angular_rate_b_rad_s;       // compensated, mid-interval
  Eigen::Vector3d specific_force_n_m_s2;      // mean over the interval
  double temp_delta_degC = 0.0;               // temperature minus reference
  double dt_s = 0.0;
  // White-noise densities the samples themselves show (vibration): the
  // model's densities are raised to these when lower (navigator.hpp).
  double accel_white_floor_m_s2_rthz = 0.0;
  double gyro_white_floor_rad_s_rthz = 0.0;
};

class ErrorStateFilter {
 public:
  void init(const StateLayout& layout, const SensorNoise& noise, const EffectTuning& tuning,
            const NavUncertainty& nav0);

  /// Propagates P and the sensor-state mean over one interval.
  void predict(const PredictInput& in);
  /// The linearised error dynamics of one interval, x+ = Phi x + w, E[w w^T] =
  /// diag(q), with `ar_steps` AR steps due (what predict() uses; the tests
  /// check it against finite differences of the strapdown step).
  void build_transition(const PredictInput& in, int ar_steps, StateMat& Phi, StateVec& q) const;

  /// Applies the correction dx (from fuse_measurement) to nav and to the
  /// sensor/effect estimates, then zeroes it.
  void feedback(StateVec& dx, NavState& nav);

  /// Raw sample -> compensated body rates (sensor-error states, scale,
  /// temperature coefficients).
  BodyRates compensate(const ImuSample& raw) const;

  const StateLayout& layout() const { return layout_; }
  StateMat& P() { return P_; }
  const StateMat& P() const { return P_; }
  /// Current estimated error of a sensor axis [m/s^2 | rad/s].
  double sensor_error(Eigen::Index axis) const;
  double sensor_error_sigma(Eigen::Index axis) const;
  /// Nominal value of effect component i (scale [-], lever arm [m], ...).
  double effect(Effect e, Eigen::Index i) const;
  void set_effect(Effect e, Eigen::Index i, double value);
  /// The tuning's given priors (EffectTuning::prior) for the active effects:
  /// their values and sigmas (after set_lever_arm / set_gps_latency, which they override).
  void apply_priors();
  /// Replaces effect e's given prior (a restart's saved state) and applies it
  /// now if e is active; a deferred e takes it when switched on.
  void set_prior(Effect e, const EffectPrior& prior);
  double effect_sigma(Effect e, Eigen::Index i) const;
  /// An effect's values (states or configured), read through its components.
  EffectView view(Effect e) const { return {value_.data() + kEffectValueOffset[static_cast<std::size_t>(e)]}; }
  Eigen::Vector3d lever_arm_b_m() const { return view(Effect::LeverArm).vec3(); }
  double gps_latency_s() const { return view(Effect::GpsLatency).scalar(); }
  Eigen::Vector3d gps_position_bias_ned_m() const { return view(Effect::GpsPositionBias).vec3(); }
  /// The GM sigma of the receiver's correlated error, per NED axis.
  Eigen::Vector3d gps_bias_sigma_ned_m() const { return gps_bias_sigma_ned_m_; }
  /// Sets the correlated error's level from a fix's stated sigma: at once
  /// (and P with it) when dt_s <= 0, else averaged. The stated variance is
  /// split: the white part is (1 - the tuning fraction) x white_scale^2 of it
  /// (white_scale learnt from the innovations: a receiver whose error is
  /// whiter than assumed), the correlated part what is left (at least 1 %).
  void set_gps_bias_sigma(const Eigen::Vector3d& fix_sigma_ned_m, double dt_s,
                          const Eigen::Vector3d& white_scale = Eigen::Vector3d::Ones());
  /// The share of a fix's stated variance that is white, per NED axis (the
  /// navigator caps white_scale so that it is at most 1: all white).
  Eigen::Vector3d gps_white_fraction_ned() const { return gps_white_fraction_ned_; }
  /// The position was just set so that measurement `m` (a GNSS fix; its
  /// position columns the identity) fits exactly: its error is then the
  /// measurement's, e_p = -(H_other e_other + w). It shares the receiver's
  /// correlated error with the GPS-bias states and the lever arm turned by
  /// the attitude error with the attitude; the latency's error times the
  /// velocity is in its variance. (A sigma that is the fix's alone claimed,
  /// after an in-motion start, a position known to 1 m along the track that
  /// a latency 0.05 s off had put 4 m behind, and the next fix "taught" the
  /// latency state a wrong value to 9 ms.)
  void seed_position_from(const Measurement& m);
  Eigen::Vector3d mag_earth_field_n_uT() const { return view(Effect::MagEarthField).vec3(); }
  Eigen::Vector3d mag_hard_iron_b_uT() const { return view(Effect::MagHardIron).vec3(); }
  /// Soft-iron matrix I + D (identity without the mag_soft_iron states).
  Eigen::Matrix3d mag_soft_iron() const { return view(Effect::MagSoftIron).identity_plus_symmetric(); }
  /// The magnetometer's axes against the body, I - [theta x] (identity without mag_misalign).
  Eigen::Matrix3d mag_misalignment() const { return misalignment_of(view(Effect::MagMisalign)); }
  /// The Earth field in the body -> the magnetometer's reading before the hard iron: S (I - [theta x]).
  Eigen::Matrix3d mag_axes() const { return mag_axes_of(view(Effect::MagSoftIron), view(Effect::MagMisalign)); }
  /// The body-frame field a reading implies, A^-1 (m - h), with the
  /// magnetometer model known so far: its states once they run, before that
  /// the priors a model file gave them (a hard iron found on an earlier
  /// flight); the reading itself when nothing is known.
  Eigen::Vector3d mag_field_b_uT(const Eigen::Vector3d& mag_b_uT) const;
  /// The same with the magnetometer effects `instead` gives (a restart's saved iron) at its values.
  Eigen::Vector3d mag_field_b_uT(const Eigen::Vector3d& mag_b_uT,
                                 const std::array<EffectPrior, kEffectCount>& instead) const;
  const EffectTuning& tuning() const { return tuning_; }
  const SensorNoise& noise() const { return noise_; }

  /// The hard iron set to what the field sample says with the current
  /// attitude and Earth field: h = m - S C_bn F, sigma `sigma_uT`, its
  /// correlations cleared.
  void reanchor_hard_iron(const NavState& nav, const Eigen::Vector3d& mag_b_uT, double sigma_uT);

  /// Switches the layout's deferred effects of `which` on: P grows by their
  /// states, with their prior variances and no correlation with the rest.
  void activate_deferred(EffectSet which);
  /// Switches the reserved vehicle_mount state on, at zero: the bracket's yaw
  /// was found from the body velocity under the heading of the moment, so its
  /// error is the heading's (the state equals the attitude error about the
  /// vertical, fully correlated) plus `independent_sigma_rad` of its own.
  void start_vehicle_mount(double independent_sigma_rad);

  /// Starts the magnetometer model from one sample: F_n = C_nb (m_b - h_b),
  /// with the uncertainty the hard iron and the sample's noise give it (none
  /// from the attitude: the field error is the invariant one).
  void start_mag_field(const NavState& nav, const Eigen::Vector3d& mag_b_uT, double noise_sigma_uT);

  /// The states of sensor axis `axis` (ax..gz): its GM/AR block and its
  /// components of the per-axis effects (bias, scale, temperature).
  void add_axis_states(Eigen::Index axis, StateMask& mask) const;
  /// Adds a navigation-frame covariance to a 3-state block (velocity or
  /// attitude): process noise the model does not carry (clipping, a gap).
  void add_block_noise(const Slice& block, const Eigen::Matrix3d& Q);
  /// Resets a 3-state block: no correlation with anything, variances sigma^2.
  void reset_block(const Slice& block, const Eigen::Vector3d& sigma);
  /// Resets state i alike: no correlation with anything, variance sigma^2.
  void reset_state(Eigen::Index i, double sigma);
  /// Turns the solution about down by dyaw [rad] (a yaw reset): the attitude
  /// down error becomes uncorrelated with variance sigma^2, the Earth-field
  /// estimate turns with the body so the magnetometer stays consistent.
  void reset_yaw(NavState& nav, double dyaw_rad, double sigma_rad);

  /// Attitude prior after an alignment: tilt and yaw sigmas.
  void seed_attitude(const Eigen::Vector3d& att_sigma_rad);
  /// At rest, after seed_attitude: along gravity the window's mean raw
  /// specific force measures the accelerometer bias (|f| - g, `sigma_along`
  /// the mean's noise); across, the levelling's "C_nb f + g_n = 0" is fused
  /// against a free tilt, so the tilt error becomes the horizontal sum of
  /// what enters f there (the bias, a misalignment's terms sensing gravity)
  /// over g, correlated with each state by its own Jacobian; the tilt keeps
  /// seed_attitude's noise on top.
  void seed_accel_bias_at_rest(NavState& nav, const Eigen::Vector3d& mean_specific_force_b_m_s2,
                               double sigma_along_m_s2);
  /// What seed_accel_bias_at_rest would measure of the accelerometer bias
  /// along gravity (u . b, u = f_b / |f_b|) [m/s^2]; the filter unchanged.
  double accel_bias_along_gravity_at_rest(const NavState& nav, const Eigen::Vector3d& mean_specific_force_b_m_s2) const;

  /// At rest, after seed_gyro_bias: the rest's mean rate is the sum of what
  /// enters the gyro there (the bias, a g-sensitivity's columns at the rest's
  /// mean specific force f_b): the bias's covariance becomes that of the sum,
  /// correlated with the others by their own Jacobians.
  void correlate_gyro_bias_at_rest(const NavState& nav, const Eigen::Vector3d& mean_specific_force_b_m_s2);
  /// Seeds the gyro bias from a mean rate the alignment measured (the Earth's
  /// rate removed) at the mean specific force f_b, and its uncertainty
  /// [rad/s]: what the model's other effects put into the gyro there (a
  /// g-sensitivity's G f, a model file's) is not the bias. Into the gyro_bias
  /// states when active, else into the sensor-error states (all lags of an
  /// AR block get the same value).
  void seed_gyro_bias(const Eigen::Vector3d& mean_rate_b_rad_s, const Eigen::Vector3d& f_b_m_s2, double sigma_rad_s);
  void set_lever_arm(const Eigen::Vector3d& l) {
    for (Eigen::Index i = 0; i < 3; ++i) set_effect(Effect::LeverArm, i, l(i));
  }
  void set_gps_latency(double s) { set_effect(Effect::GpsLatency, 0, s); }
  void set_reference_temperature(double t) { temp_ref_degC_ = t; }
  double reference_temperature() const { return temp_ref_degC_; }

 private:
  void apply_prior(Effect e);
  /// seed_gyro_bias's value and sigma into the states (see there).
  void put_gyro_bias(const Eigen::Vector3d& bias_rad_s, double sigma_rad_s);
  /// A rest window's mean specific force, compensated with the current estimates.
  BodyRates compensate_at_rest(const Eigen::Vector3d& f_b) const;
  /// The accelerometer bias with its part along gravity as the rest measures
  /// it, |f| - g of the mean compensated with the current estimates.
  Eigen::Vector3d accel_bias_measured_at_rest(const NavState& nav, const Eigen::Vector3d& f_b) const;
  /// The error dynamics' rate rows (`rows`: the velocity's or the attitude's)
  /// at rest with specific force f_b: the columns of the states that enter a
  /// rest window's mean; the navigation states' zero but, with_tilt, the
  /// tilt's (about north and east); the coloured error's zero.
  MeasJacobian rest_rows(const NavState& nav, const Eigen::Vector3d& f_b, Eigen::Index rows, bool with_tilt) const;
  /// The largest coloured-error variance of a triad (its first sensor axis).
  double coloured_variance(Eigen::Index first_axis) const;
  double* values(Effect e) { return value_.data() + kEffectValueOffset[static_cast<std::size_t>(e)]; }
  static Eigen::Matrix3d misalignment_of(EffectView theta) { return Eigen::Matrix3d::Identity() - skew(theta.vec3()); }
  static Eigen::Matrix3d mag_axes_of(EffectView soft_iron, EffectView misalign) {
    return soft_iron.identity_plus_symmetric() * misalignment_of(misalign);
  }
  struct FeedbackTerms;  // what an effect's feedback may use (error_state_filter.cpp)
  Eigen::Index hat_index(Eigen::Index axis) const { return axis * layout_.order; }
  /// P <- G P G^T for a 3-state block: a reset Jacobian.
  void rotate_block(const Slice& block, const Eigen::Matrix3d& G);
  /// Attitude noise Q_att with what it does to the invariant field error.
  void add_field_coupled_noise(const Eigen::Matrix3d& Q_att, bool attitude_block_too);

  StateLayout layout_;
  SensorNoise noise_;
  EffectTuning tuning_;
  StateMat P_;
  StateVec sensor_hat_;  // mean of the sensor-error states (size sensor.size)
  std::array<AxisBlock, kSensorAxes> ar_step_{};  // companion matrices
  double ar_clock_s_ = 0.0;
  // Every effect's values, states or configured (lever arm, latency), in the
  // effects' own components (effects/*.hpp); zero is the nominal sensor.
  std::array<double, kMaxEffectStates> value_{};
  Eigen::Vector3d gps_bias_sigma_ned_m_ = Eigen::Vector3d::Ones();
  Eigen::Vector3d gps_white_fraction_ned_ = Eigen::Vector3d::Constant(0.1);
  double temp_ref_degC_ = 0.0;
};

}  // namespace sinu::est
