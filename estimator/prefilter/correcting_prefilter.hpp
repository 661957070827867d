#pragma once
// Known, fixed corrections of the accelerometer in front of the denoiser:
//   f = K (f_raw - b)
// from a multi-position bench calibration of the unit (calib.json
// "six_position": K = ((I + diag s)(I + M))^-1 undoes its scale factors and
// misalignment, b is its bias then). Applied after the screen, so clipping is
// judged on the raw values, and before the denoiser, which is linear and the
// same on every axis: the order does not change the result. The filter's
// accel_bias state then holds only what changed since the calibration.
#include <Eigen/Core>

#include "estimator/prefilter/imu_prefilter.hpp"

namespace sinu::est {

class CorrectingPrefilter final : public ImuPrefilter {
 public:
  /// `inner` (not owned) runs after the correction; nullptr: none.
  CorrectingPrefilter(ImuPrefilter* inner, const Eigen::Matrix3d& K, const Eigen::Vector3d& bias_m_s2)
      : inner_(inner ? inner : &pass_), K_(K), b_(bias_m_s2) {}
  int delay_samples() const override { return inner_->delay_samples(); }
  bool push(const ImuSample& in, ImuSample& out) override {
    ImuSample c = in;
    c.specific_force_b_m_s2 = K_ * (in.specific_force_b_m_s2 - b_);
    return inner_->push(c, out);
  }
  bool drain(ImuSample& out) override { return inner_->drain(out); }

 private:
  PassThroughPrefilter pass_;
  ImuPrefilter* inner_;
  Eigen::Matrix3d K_;
  Eigen::Vector3d b_;
};

}  // namespace sinu::est
