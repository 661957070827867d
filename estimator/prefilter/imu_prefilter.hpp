#pragma once
// The seam for the wavelet denoiser (issue 4) in front of the INS. A
// prefilter consumes raw samples and emits filtered ones `delay_samples()`
// later; each output carries the time stamp of the instant it describes
// (input time minus the delay), so the INS and the measurement time line stay
// consistent and the delay is accounted for by the delayed-fusion horizon.
// Implementations must not allocate in push().
#include "estimator/ins/imu_sample.hpp"

namespace sinu::est {

class ImuPrefilter {
 public:
  virtual ~ImuPrefilter() = default;
  /// Group delay in input samples (0 for a pass-through).
  virtual int delay_samples() const = 0;
  /// Feeds one raw sample; true when `out` holds the next filtered sample.
  virtual bool push(const ImuSample& in, ImuSample& out) = 0;
  /// End of data: true while samples still held back come out.
  virtual bool drain(ImuSample&) { return false; }
};

/// No filtering, no delay.
class PassThroughPrefilter final : public ImuPrefilter {
 public:
  int delay_samples() const override { return 0; }
  bool push(const ImuSample& in, ImuSample& out) override {
    out = in;
    return true;
  }
};

}  // namespace sinu::est
