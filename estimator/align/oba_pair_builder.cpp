#include "estimator/align/oba_pair_builder.hpp"

#include <algorithm>
#include <cmath>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::est {

ObaVector make_pair(const Eigen::Vector3d& beta, const Eigen::Vector3d& alpha, const Eigen::Matrix3d& D,
                    const Eigen::Matrix3d& A, const Eigen::Matrix3d& D1) {
  ObaVector u;
  u << beta, alpha, D.reshaped(), A.reshaped(), D1.reshaped();
  return u;
}

ObaGram gyro_correction_map(const Eigen::Vector3d& delta) {
  // alpha_i += sum_j D(i, j) delta_j; D(i, j) sits at 6 + 3 j + i (column-major).
  ObaGram T = ObaGram::Identity();
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) T(3 + i, 6 + 3 * j + i) = delta(j);
  }
  return T;
}

void ObaPairBuilder::reset() {
  head_ = size_ = half_span_ = 0;
  epochs_ = 0;
  t_prev_s_ = v_down_m_s_ = vertical_var_m2_s2_ = 0.0;
  kappa_ = 1.0;
  q_n0n_.setIdentity();
  w_in_prev_rad_s_.setZero();
  y_prev_n0_m_s2_.setZero();
  integral_n0_m_s_.setZero();
  done_gg_.setZero();
  done_gamma_g_.setZero();
  done_gamma2_ = 0.0;
}

double ObaPairBuilder::horizontal_variance_m2_s2() const {
  return kappa_ * noise_.velocity_sigma_m_s * noise_.velocity_sigma_m_s;
}

void ObaPairBuilder::update_navigation_frame(const GnssObservation& z, double t_s) {
  // Rotation of n and the gravity/Coriolis integrand. This epoch's v_down is
  // not known yet (centre-of-fit delay): the latest slope is used in the
  // Earth-rate term, where 1 m/s of error is 6e-5 m/s^2.
  const Eigen::Vector3d v_n_m_s(z.v_ne_m_s.x(), z.v_ne_m_s.y(), v_down_m_s_);
  const Eigen::Vector3d w_ie_rad_s = wgs84::omega_ie_n(z.lat_rad);
  const Eigen::Vector3d w_in_rad_s = w_ie_rad_s + wgs84::omega_en_n(z.lat_rad, z.h_m, v_n_m_s);
  const Eigen::Vector3d g_n_m_s2(0.0, 0.0, wgs84::normal_gravity_m_s2(z.lat_rad, z.h_m));
  const double dt_s = t_s - t_prev_s_;
  if (epochs_ > 0) {
    q_n0n_ = (q_n0n_ * quat_from_rotation_vector(0.5 * (w_in_prev_rad_s_ + w_in_rad_s) * dt_s)).normalized();
  }
  const Eigen::Vector3d y_n0_m_s2 = q_n0n_ * (g_n_m_s2 - w_ie_rad_s.cross(v_n_m_s));
  if (epochs_ > 0) integral_n0_m_s_ += 0.5 * dt_s * (y_prev_n0_m_s2_ + y_n0_m_s2);
  w_in_prev_rad_s_ = w_in_rad_s;
  y_prev_n0_m_s2_ = y_n0_m_s2;

  // Height-fit span and the velocity-correlation factor, from the first interval.
  if (epochs_ == 1) {
    const long m = std::lround(noise_.height_fit_s / (2.0 * dt_s));
    half_span_ = static_cast<int>(std::clamp(m, 1L, static_cast<long>(kMaxHalfSpan)));
    const double rho = noise_.velocity_corr_s > 0.0 ? std::exp(-dt_s / noise_.velocity_corr_s) : 0.0;
    kappa_ = (1.0 + rho) / (1.0 - rho);
  }
  t_prev_s_ = t_s;
  ++epochs_;
}

bool ObaPairBuilder::add_epoch(const GnssObservation& z, double t_s, const ObaVector& body, ObaVector& pair) {
  update_navigation_frame(z, t_s);
  // Store the epoch (the ring never overflows: form_pair pops one).
  Epoch& e = at(size_);
  const Eigen::Matrix3d C_n0n = q_n0n_.toRotationMatrix();
  e.t_s = t_s;
  e.h_m = z.h_m;
  e.beta_h_n0_m_s = C_n0n * Eigen::Vector3d(z.v_ne_m_s.x(), z.v_ne_m_s.y(), 0.0) - integral_n0_m_s_;
  e.down_n0 = C_n0n.col(2);
  e.body = body;
  e.g.setZero();
  e.gamma = 0.0;
  ++size_;
  if (half_span_ == 0 || size_ < 2 * half_span_ + 1) return false;
  form_pair(pair);
  return true;
}

void ObaPairBuilder::form_pair(ObaVector& pair) {
  // Least-squares height slope over the 2m+1 epochs: v_down at the centre one,
  // v_down = sum_i c_i h_i with c_i = -(t_i - t_mean) / sum (t_j - t_mean)^2.
  const int n = 2 * half_span_ + 1;
  double t_mean_s = 0.0;
  for (int i = 0; i < n; ++i) t_mean_s += at(i).t_s;
  t_mean_s /= static_cast<double>(n);
  double sxx_s2 = 0.0, sxh_m_s = 0.0;
  for (int i = 0; i < n; ++i) {
    const double dt_s = at(i).t_s - t_mean_s;
    sxx_s2 += dt_s * dt_s;
    sxh_m_s += dt_s * at(i).h_m;
  }
  v_down_m_s_ = -sxh_m_s / sxx_s2;
  if (vertical_var_m2_s2_ == 0.0) vertical_var_m2_s2_ = noise_.height_sigma_m * noise_.height_sigma_m / sxx_s2;

  // The pair at the centre epoch.
  const Epoch& c = at(half_span_);
  pair = c.body;
  pair.segment<3>(0) = c.beta_h_n0_m_s + c.down_n0 * v_down_m_s_;

  // Each height's share of this pair's v_down; the oldest height is complete.
  for (int i = 0; i < n; ++i) {
    const double c_i = -(at(i).t_s - t_mean_s) / sxx_s2;
    at(i).g += c_i * pair;
    at(i).gamma += c_i;
  }
  const Epoch& old = at(0);
  done_gg_ += old.g * old.g.transpose();
  done_gamma_g_ += old.gamma * old.g;
  done_gamma2_ += old.gamma * old.gamma;
  head_ = (head_ + 1) % kCapacity;
  --size_;
}

ObaGram ObaPairBuilder::height_noise_gram(const ObaVector& u_mean) const {
  // Completed heights from the running sums, the ones still in the ring directly.
  ObaGram G = done_gg_ - done_gamma_g_ * u_mean.transpose() - u_mean * done_gamma_g_.transpose() +
              done_gamma2_ * u_mean * u_mean.transpose();
  for (int i = 0; i < size_; ++i) {
    const ObaVector h = at(i).g - at(i).gamma * u_mean;
    G += h * h.transpose();
  }
  return G;
}

void ObaPairBuilder::correct_gyro_bias(const Eigen::Vector3d& delta) {
  const ObaGram T = gyro_correction_map(delta);
  for (int i = 0; i < size_; ++i) {
    at(i).body = T * at(i).body;
    at(i).g = T * at(i).g;
  }
  done_gg_ = T * done_gg_ * T.transpose();
  done_gamma_g_ = T * done_gamma_g_;
}

}  // namespace sinu::est
