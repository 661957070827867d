#include "firmware/host/sim/error_processes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sinu::sim {

void GaussMarkov::init(double sigma, double tau_s, double dt_s, Rng& rng) {
  phi_ = tau_s > 0.0 ? std::exp(-dt_s / tau_s) : 0.0;
  drive_ = sigma * std::sqrt(1.0 - phi_ * phi_);
  x_ = sigma * rng.normal();
}

double GaussMarkov::step(Rng& rng) {
  x_ = phi_ * x_ + drive_ * rng.normal();
  return x_;
}

void PeriodicRandom::init(double sigma, double period_s, double zeta, double dt_s, Rng& rng) {
  const double w_d = 2.0 * std::numbers::pi / period_s;
  const double w0 = w_d / std::sqrt(1.0 - zeta * zeta);
  const double r = std::exp(-zeta * w0 * dt_s);
  a1_ = 2.0 * r * std::cos(w_d * dt_s);
  a2_ = -r * r;
  // Stationary variance of x_k = a1 x_{k-1} + a2 x_{k-2} + e_k:
  //   var = (1 - a2) / ((1 + a2) ((1 - a2)^2 - a1^2)) var(e).
  const double gain = (1.0 - a2_) / ((1.0 + a2_) * ((1.0 - a2_) * (1.0 - a2_) - a1_ * a1_));
  drive_ = sigma / std::sqrt(gain);
  // Stationary start: x1 ~ N(0, sigma^2), x2 with lag-1 correlation rho1 = a1 / (1 - a2).
  const double rho1 = a1_ / (1.0 - a2_);
  x2_ = sigma * rng.normal();
  x1_ = rho1 * x2_ + sigma * std::sqrt(std::max(0.0, 1.0 - rho1 * rho1)) * rng.normal();
}

double PeriodicRandom::step(Rng& rng) {
  const double x = a1_ * x1_ + a2_ * x2_ + drive_ * rng.normal();
  x2_ = x1_;
  x1_ = x;
  return x;
}

void RandomWalk::init(double k, double dt_s) {
  drive_ = k * std::sqrt(dt_s);
  x_ = 0.0;
}

double RandomWalk::step(Rng& rng) {
  x_ += drive_ * rng.normal();
  return x_;
}

}  // namespace sinu::sim
