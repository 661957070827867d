#pragma once
// In-motion coarse alignment: the full attitude while moving, from the IMU
// and GNSS velocity, by optimisation-based alignment (OBA) in its
// velocity-integration form, solved as Wahba's problem and refined jointly
// with the gyro and accelerometer biases:
//   b0, n0: body and navigation frames at the window start t0 (fixed in
//   inertial space); C_nb(t) = C_n_n0(t) C_n0_b0 C_b0_b(t), where C_b0_b
//   comes from the gyros, C_n_n0 from the Earth and transport rates, and
//   C_n0_b0 is the one unknown attitude, fitted to pairs
//   beta_k = C_n0_b0 alpha_k + c at the GNSS epochs (oba_body_integrals,
//   oba_pair_builder, oba_solver; docs/in_motion_alignment.md derives it).
//
// Observability: tilt comes from gravity, yaw needs the horizontal velocity
// to change (speed changes, turns) so that the pairs are not all collinear.
// The criterion is the yaw 1-sigma of the first-order error model (GNSS
// velocity and height noise, gyro bias prior, accelerometer bias over the
// window) against max_yaw_sigma_rad. For white velocity noise only it is
// about sqrt(12 / N) sigma_v / (spread of the horizontal velocity change).
// During a steady acceleration (constant turn or speed change) the weak axis
// is the specific force, not down, so tilt shares the yaw uncertainty then.
//
// Window: starts at the first usable GNSS epoch (position and velocity);
// restarts when epochs stop for more than max_gnss_gap_s, after an IMU gap
// or bad sample, and when it would exceed max_window_s. A solution is
// reported at every epoch from min_window_s on, flagged with yaw_observable.
// Each solution's gyro bias estimate is fed back (removed from the gyro and
// from the window's integrals, oba_body_integrals.hpp), so the first-order
// bias model stays valid over the window; the last estimate made while the
// fit is linear (tilt sigma < 2 deg, yaw sigma < 20 deg), with its
// covariance, is the next window's prior. reset() forgets both.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <numbers>

#include "estimator/align/oba_body_integrals.hpp"
#include "estimator/align/oba_pair_builder.hpp"
#include "estimator/align/oba_solver.hpp"
#include "estimator/ekf/aiding/gnss_observation.hpp"
#include "estimator/ins/imu_sample.hpp"

namespace sinu::est {

struct InMotionAlignmentConfig {
  double min_window_s = 3.0;
  double max_window_s = 20.0;             // the sigmas stay honest to ~20 s (docs/in_motion_alignment.md)
  double max_gnss_gap_s = 1.0;
  double max_imu_gap_s = 0.1;
  double max_yaw_sigma_rad = 3.0 * std::numbers::pi / 180.0;
  double gnss_velocity_sigma_m_s = 0.2;   // horizontal, per epoch (the epoch's own sigma is not used)
  double gnss_velocity_corr_s = 0.5;      // correlation time of that error (0: white)
  double gnss_height_sigma_m = 1.0;       // per epoch, white part
  double height_fit_s = 2.0;              // span of the height-slope fit (v_down)
  double gyro_bias_sigma_rad_s = 0.5 * std::numbers::pi / 180.0;  // prior (turn-on bias), per axis
  double gyro_bias_walk_rad_s_rt_s = 1e-5;  // bias drift between windows (its prior grows by walk^2 dt)
  double accel_bias_sigma_m_s2 = 0.3;     // prior (turn-on bias), per axis
  double gyro_arw_rad_rt_s = 2.6e-4;      // gyro white noise (consumer MEMS, 0.015 deg/s/rtHz)
  Eigen::Vector3d lever_arm_b_m = Eigen::Vector3d::Zero();  // GNSS antenna from the IMU, body FRD
};

struct InMotionSolution {
  double t_s = 0.0;
  Eigen::Quaterniond q_nb = Eigen::Quaterniond::Identity();  // yaw meaningless unless yaw_observable
  /// 1-sigma of the attitude error phi (C_nb_hat = (I - [phi x]) C_nb, the
  /// EKF's att state) in NED: north and east tilt, down = yaw; and its
  /// covariance. Yaw sigma pi/sqrt(3) (uniform) when it has no information.
  Eigen::Vector3d att_sigma_rad = Eigen::Vector3d::Zero();
  Eigen::Matrix3d att_cov_rad2 = Eigen::Matrix3d::Zero();
  bool yaw_observable = false;
  /// The window's constant gyro bias (measured - true), body axes, and its 1-sigma.
  Eigen::Vector3d gyro_bias_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_bias_sigma_rad_s = Eigen::Vector3d::Zero();
  double window_s = 0.0;
};

class InMotionAlignment {
 public:
  void configure(const InMotionAlignmentConfig& cfg);
  void reset();
  /// Raw IMU samples in time order; dt_s to the previous sample.
  void add_imu(const ImuSample& s, double dt_s);
  /// A GNSS epoch whose time of validity is the current IMU instant t_now_s
  /// (the caller handles latency). True and `out` filled when a solution is available.
  bool add_gnss(const GnssObservation& z, double t_now_s, InMotionSolution& out);

 private:
  void start_window(double t_now_s);

  InMotionAlignmentConfig cfg_;
  ObaBodyIntegrals body_;
  ObaPairBuilder pairs_;
  ObaSolver solver_;
  ImuSample prev_;           // raw
  bool have_prev_ = false;   // prev_ is a good sample
  Eigen::Vector3d gyro_comp_rad_s_ = Eigen::Vector3d::Zero();  // bias removed before integration
  // Gyro bias prior of the current window, and the candidate for the next one.
  Eigen::Vector3d bias_prior_rad_s_ = Eigen::Vector3d::Zero(), bias_next_rad_s_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d bias_prior_cov_ = Eigen::Matrix3d::Identity(), bias_next_cov_ = Eigen::Matrix3d::Identity();
  double bias_next_t_s_ = 0.0;  // when bias_next_ was estimated (0: the configured prior)
  bool imu_broken_ = true;   // a gap or bad sample since the window started
  bool active_ = false;
  double t0_s_ = 0.0, t_last_gnss_s_ = 0.0;
};

}  // namespace sinu::est
