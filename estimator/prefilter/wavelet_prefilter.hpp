#pragma once
// The paper's denoiser in front of the INS: each accelerometer and gyro axis
// through its own streaming wavelet denoiser (level-L approximation, issue 4).
// Outputs come out kDelay samples late and carry the time stamp (and the
// magnetometer and temperature) of the instant they describe, so the INS and
// the GNSS time line stay consistent (see imu_prefilter.hpp). The
// magnetometer and temperature are passed through, delayed, not filtered.
// Details above a channel's thresholds (a few sigma of the unit's noise at
// that level, from its bench session) are kept: fast motion passes.
// Storage is inside the object: no heap after make_wavelet_prefilter().
#include <array>
#include <limits>
#include <memory>

#include "estimator/prefilter/imu_prefilter.hpp"
#include "estimator/util/ring_buffer.hpp"
#include "estimator/wavelet/denoiser_select.hpp"

namespace sinu::est {

inline constexpr std::size_t kPrefilterCapacity = 1024;  // samples held while the denoiser delays them

/// Per channel (ax ay az [m/s^2], gx gy gz [rad/s]) and level (index 0: the
/// finest): a detail larger than this is kept; infinity drops it (the paper).
using DetailThresholds = std::array<std::array<double, wavelet::kMaxLevels>, 6>;

inline DetailThresholds drop_every_detail() {
  DetailThresholds t;
  for (auto& c : t) c.fill(std::numeric_limits<double>::infinity());
  return t;
}

template <class Denoiser>
class WaveletPrefilter final : public ImuPrefilter {
  static_assert(Denoiser::kDelay < static_cast<int>(kPrefilterCapacity), "denoiser delay exceeds the sample buffer");

 public:
  explicit WaveletPrefilter(const DetailThresholds& keep_above = drop_every_detail()) {
    for (std::size_t c = 0; c < channel_.size(); ++c) {
      typename Denoiser::Thresholds t;
      for (std::size_t j = 0; j < t.size(); ++j) t[j] = keep_above[c][j];
      channel_[c].keep_details_above(t);
    }
  }

  int delay_samples() const override { return Denoiser::kDelay; }

  bool push(const ImuSample& in, ImuSample& out) override {
    if (!started_) {
      // Prime every channel with the first sample: no start-up ramp from zero.
      for (Eigen::Index i = 0; i < 3; ++i) {
        channel_[static_cast<std::size_t>(i)].reset(in.specific_force_b_m_s2(i));
        channel_[static_cast<std::size_t>(i + 3)].reset(in.angular_rate_b_rad_s(i));
      }
      started_ = true;
    }
    last_ = in;
    held_.push(in);
    Eigen::Vector3d f, w;
    for (Eigen::Index i = 0; i < 3; ++i) {
      f(i) = channel_[static_cast<std::size_t>(i)].step(in.specific_force_b_m_s2(i));
      w(i) = channel_[static_cast<std::size_t>(i + 3)].step(in.angular_rate_b_rad_s(i));
    }
    if (held_.size() <= static_cast<std::size_t>(Denoiser::kDelay)) return false;
    out = held_.front();
    held_.pop();
    out.specific_force_b_m_s2 = f;
    out.angular_rate_b_rad_s = w;
    return true;
  }

  /// End of data: the last input repeated until every held sample is out.
  bool drain(ImuSample& out) override {
    if (held_.empty()) return false;
    Eigen::Vector3d f, w;
    for (Eigen::Index i = 0; i < 3; ++i) {
      f(i) = channel_[static_cast<std::size_t>(i)].step(last_.specific_force_b_m_s2(i));
      w(i) = channel_[static_cast<std::size_t>(i + 3)].step(last_.angular_rate_b_rad_s(i));
    }
    out = held_.front();
    held_.pop();
    out.specific_force_b_m_s2 = f;
    out.angular_rate_b_rad_s = w;
    return true;
  }

 private:
  std::array<Denoiser, 6> channel_;  // ax ay az gx gy gz
  RingBuffer<ImuSample, kPrefilterCapacity> held_;
  ImuSample last_;
  bool started_ = false;
};

/// The wavelet prefilter named at run time (levels 1..wavelet::kMaxLevels).
std::unique_ptr<ImuPrefilter> make_wavelet_prefilter(wavelet::WaveletKind kind, int levels,
                                                     const DetailThresholds& keep_above = drop_every_detail());

}  // namespace sinu::est
