#pragma once
// Navigation side of optimisation-based alignment: turns GNSS epochs into
// vector pairs (beta in n0, alpha in b0) with beta = C_n0_b0 alpha + c
// (c: one unknown constant per window, the initial velocity).
//
// With C_nb = C_n_n0 C_n0_b0 C_b0_b and the NED velocity equation
// dv/dt = C_nb f + g - (2 w_ie + w_en) x v, integrating d(C_n0_n v)/dt
// (C_n0_n rotates at w_in = w_ie + w_en) gives exactly
//   beta(t) = C_n0_n(t) v(t) - int_t0^t C_n0_n (g - w_ie x v) dtau = C_n0_b0 alpha(t) + c.
// The rotation of n over the window is kept (ignoring it tilts the result by
// |w_in| t: 0.03 deg after 10 s, 0.1 deg after 30 s). C_n0_n and the
// integral are trapezoidal between epochs; g = normal gravity (lat, h).
//
// NMEA has no vertical velocity: v_down is minus the least-squares slope of
// the heights of 2m+1 consecutive epochs, which for evenly spaced epochs is
// the derivative at the centre epoch (exact for a quadratic height). Each
// pair is formed at the centre epoch, m epochs after it arrived; epochs wait
// in a fixed-size ring. m = round(height_fit_s / (2 epoch interval)), fixed
// at the window's second epoch, 1..kMaxHalfSpan.
//
// Noise. Horizontal: white per pair, variance kappa sigma_v^2 with kappa =
// (1 + rho) / (1 - rho), rho = exp(-dt / tau), the sum of the
// autocorrelation of a first-order Gauss-Markov error (correlation time tau,
// epoch interval dt), so independent pairs carry the right total weight.
// Vertical: v_down_k = sum_i c_ki h_i, so the overlapping fits are strongly
// correlated; their effect on any linear function sum_k J(u_k) of the pairs
// is carried exactly by g_i = sum_k c_ki u_k (one per height), summarised
// in height_noise_gram() (the solver multiplies by sigma_h^2).
#include <array>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "estimator/ekf/aiding/gnss_observation.hpp"

namespace sinu::est {

/// A pair as one vector u = [beta (n0), alpha (b0), vec D, vec A, vec D1]
/// (the sensitivities of oba_body_integrals.hpp, column-major), so every sum
/// the solver needs is a quadratic form in u.
inline constexpr int kObaPairSize = 33;
using ObaVector = Eigen::Matrix<double, kObaPairSize, 1>;
using ObaGram = Eigen::Matrix<double, kObaPairSize, kObaPairSize>;
inline Eigen::Vector3d pair_beta(const ObaVector& u) { return u.segment<3>(0); }
inline Eigen::Vector3d pair_alpha(const ObaVector& u) { return u.segment<3>(3); }
inline Eigen::Matrix3d pair_D(const ObaVector& u) { return Eigen::Map<const Eigen::Matrix3d>(u.data() + 6); }
inline Eigen::Matrix3d pair_A(const ObaVector& u) { return Eigen::Map<const Eigen::Matrix3d>(u.data() + 15); }
inline Eigen::Matrix3d pair_D1(const ObaVector& u) { return Eigen::Map<const Eigen::Matrix3d>(u.data() + 24); }
ObaVector make_pair(const Eigen::Vector3d& beta, const Eigen::Vector3d& alpha, const Eigen::Matrix3d& D,
                    const Eigen::Matrix3d& A, const Eigen::Matrix3d& D1);
/// The linear map u -> u with alpha += D delta: a pair re-expressed after
/// `delta` more gyro bias is removed (ObaBodyIntegrals::correct_gyro_bias).
ObaGram gyro_correction_map(const Eigen::Vector3d& delta_rad_s);

struct ObaPairNoise {
  double velocity_sigma_m_s = 0.2;
  double velocity_corr_s = 0.5;
  double height_sigma_m = 1.0;
  double height_fit_s = 2.0;
};

class ObaPairBuilder {
 public:
  static constexpr int kMaxHalfSpan = 10;

  void configure(const ObaPairNoise& noise) { noise_ = noise; }
  void reset();
  /// A GNSS epoch (with position and velocity) valid at t_s, and the body
  /// side at that instant (`body`; its beta part is ignored). True when the
  /// pair of the epoch m epochs back is ready in `pair`.
  bool add_epoch(const GnssObservation& z, double t_s, const ObaVector& body, ObaVector& pair);

  /// C_n0_n at the latest epoch.
  Eigen::Matrix3d C_n0n() const { return q_n0n_.toRotationMatrix(); }
  /// Per-pair variances of beta: horizontal (each axis), vertical (white approximation, for weights).
  double horizontal_variance_m2_s2() const;
  double vertical_variance_m2_s2() const { return vertical_var_m2_s2_; }
  /// sum_i (g_i - gamma_i u_mean)(g_i - gamma_i u_mean)^T, gamma_i = sum_k c_ki:
  /// the v_down noise of the centred pairs is sum_i (g_i - gamma_i u_mean) e_i, e_i the height error.
  ObaGram height_noise_gram(const ObaVector& u_mean) const;
  /// Applies gyro_correction_map(delta) to every stored pair and height term.
  void correct_gyro_bias(const Eigen::Vector3d& delta_rad_s);

 private:
  struct Epoch {
    double t_s = 0.0, h_m = 0.0;
    Eigen::Vector3d beta_h_n0_m_s = Eigen::Vector3d::Zero();  // beta without the v_down term
    Eigen::Vector3d down_n0 = Eigen::Vector3d::Zero();        // C_n0_n e_down: beta = beta_h + down v_down
    ObaVector body = ObaVector::Zero();
    ObaVector g = ObaVector::Zero();  // sum_k c_ki u_k so far
    double gamma = 0.0;               // sum_k c_ki so far
  };
  static constexpr int kCapacity = 2 * kMaxHalfSpan + 1;
  Epoch& at(int i) { return ring_[static_cast<std::size_t>((head_ + i) % kCapacity)]; }
  const Epoch& at(int i) const { return ring_[static_cast<std::size_t>((head_ + i) % kCapacity)]; }
  void update_navigation_frame(const GnssObservation& z, double t_s);
  void form_pair(ObaVector& pair);

  ObaPairNoise noise_;
  std::array<Epoch, kCapacity> ring_{};
  int head_ = 0, size_ = 0, half_span_ = 0;  // half_span_ 0: not yet known
  long epochs_ = 0;
  double t_prev_s_ = 0.0, kappa_ = 1.0, v_down_m_s_ = 0.0, vertical_var_m2_s2_ = 0.0;
  Eigen::Quaterniond q_n0n_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d w_in_prev_rad_s_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d y_prev_n0_m_s2_ = Eigen::Vector3d::Zero();  // integrand C_n0_n (g - w_ie x v)
  Eigen::Vector3d integral_n0_m_s_ = Eigen::Vector3d::Zero();
  // Heights that left the ring: sum g g^T, sum gamma g, sum gamma^2.
  ObaGram done_gg_ = ObaGram::Zero();
  ObaVector done_gamma_g_ = ObaVector::Zero();
  double done_gamma2_ = 0.0;
};

}  // namespace sinu::est
