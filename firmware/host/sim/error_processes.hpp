#pragma once
// Scalar stochastic processes of the sensor error model, each advanced once
// per sample of period dt [s] and started in its stationary distribution.
#include "firmware/host/sim/rng.hpp"

namespace sinu::sim {

/// First-order Gauss-Markov: b' = -b/tau + w, stationary std `sigma`.
/// Exact discretisation b_k = exp(-dt/tau) b_{k-1} + sigma sqrt(1-exp(-2dt/tau)) n_k.
class GaussMarkov {
 public:
  void init(double sigma, double tau_s, double dt_s, Rng& rng);
  double step(Rng& rng);
  double value() const { return x_; }

 private:
  double phi_ = 0.0, drive_ = 0.0, x_ = 0.0;
};

/// Periodic-random component: white noise through a lightly damped
/// second-order resonator x'' + 2 zeta w0 x' + w0^2 x = w, sampled at dt.
/// The sampled process is exactly AR(2) with poles r e^{+-j w_d dt},
/// r = exp(-zeta w0 dt), w_d = w0 sqrt(1 - zeta^2); the driving variance is
/// set so the stationary std is `sigma`. Its autocorrelation is a damped
/// cosine with period `period_s` = 2 pi / w_d, which is what a first-order
/// GM model cannot represent (paper, Figs. 5-6).
class PeriodicRandom {
 public:
  void init(double sigma, double period_s, double damping_ratio, double dt_s, Rng& rng);
  double step(Rng& rng);
  double value() const { return x1_; }
  double a1() const { return a1_; }
  double a2() const { return a2_; }

 private:
  double a1_ = 0.0, a2_ = 0.0, drive_ = 0.0, x1_ = 0.0, x2_ = 0.0;
};

/// Random walk: r_k = r_{k-1} + K sqrt(dt) n_k, starting at 0.
/// K [unit/sqrt(s)]: e.g. gyro rate random walk in rad/s/sqrt(s).
class RandomWalk {
 public:
  void init(double k_per_sqrt_s, double dt_s);
  double step(Rng& rng);
  double value() const { return x_; }

 private:
  double drive_ = 0.0, x_ = 0.0;
};

}  // namespace sinu::sim
