#pragma once
// The receiver's slowly varying position error (atmosphere, multipath,
// orbits), NED [m]: a first-order Gauss-Markov process per axis whose level
// is a fraction of the fix's stated variance (EffectTuning), fix = antenna + b.
// The fix's variance is split: the correlated part lives in these states,
// the rest is white (ErrorStateFilter::set_gps_bias_sigma: the split is
// learnt from the innovations).
#include <cmath>

#include "estimator/ekf/effects/effect_spec.hpp"

namespace sinu::est::effects {

struct GpsPositionBias {
  static constexpr EffectSpec spec{Effect::GpsPositionBias, "gps_position_bias", Components::Xyz, "m", 1.0, 1.5, 0.0,
                                   false, 50.0};
  template <class T> static void gnss_position(EffectView v, T& t) {
    if (!t.slice.active()) return;
    t.measurement_offset_n += v.vec3();
    t.H.block(0, t.slice.start, 3, 3) = -Eigen::Matrix3d::Identity();
    t.white_variance = t.white_variance.cwiseProduct(t.white_fraction);
  }
  /// First-order GM per NED axis at the level the fixes state.
  template <class T> static void process_noise(EffectView, T& t) {
    const double phi = std::exp(-t.dt / t.tuning.gps_bias_tau_s);
    for (Eigen::Index j = 0; j < 3; ++j) {
      t.Phi(t.slice.start + j, t.slice.start + j) = phi;
      t.q(t.slice.start + j) = t.gps_bias_sigma_ned_m(j) * t.gps_bias_sigma_ned_m(j) * (1.0 - phi * phi);
    }
  }
  /// The estimate decays as the process does.
  template <class T> static void predict_mean(double* v, const T& t) {
    const double decay = std::exp(-t.dt / t.tuning.gps_bias_tau_s);
    for (int j = 0; j < 3; ++j) v[j] *= decay;
  }
};

}  // namespace sinu::est::effects
