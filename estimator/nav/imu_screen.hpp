#pragma once
// Screens raw IMU samples before anything filters them: drops a sample with
// a non-finite value or a time that does not increase (a live stream can
// repeat or step back), and marks the axes at full scale.
//
// Clipping: an axis is clipped when its magnitude reaches `clip_fraction` of
// the configured full scale (the driver knows it; a dataset user gives it),
// or, with the full scale unknown, when it sits flat above `flat_top_*`
// for `flat_top_repeats` samples in a row near one of the full scales MEMS
// converters come in (imu_screen.cpp), `flat_top_repeats_anywhere` elsewhere:
// a clipped converter repeats its extreme code exactly, a live signal with
// noise rarely does, and seldom for long. The value
// found flat is remembered as that axis's rail (either sign): from then on
// every sample at the rail is clipped, also single ones in a vibration burst.
#include <array>
#include <cstdint>

#include "estimator/ins/imu_sample.hpp"

namespace sinu::est {

struct ImuScreenConfig {
  double accel_range_m_s2 = 0.0;    // full scale; 0: unknown (flat-top detection only)
  double gyro_range_rad_s = 0.0;
  double clip_fraction = 0.98;
  double flat_top_accel_m_s2 = 14.7;  // 1.5 g
  double flat_top_rate_rad_s = 3.0;
  int flat_top_repeats = 3;           // near a common full scale (imu_screen.cpp)
  int flat_top_repeats_anywhere = 10;  // elsewhere (a +-5-g or +-300-deg/s part)
};

enum class ScreenVerdict { Keep, NonFinite, NotIncreasing };

class ImuScreen {
 public:
  void configure(const ImuScreenConfig& cfg);
  /// Judges one raw sample; on Keep, `clipped_axes` has bit a set for each
  /// clipped axis a (ax ay az gx gy gz).
  ScreenVerdict screen(const ImuSample& raw, std::uint8_t& clipped_axes);

 private:
  ImuScreenConfig cfg_;
  bool have_last_ = false;
  double last_t_s_ = 0.0;
  std::array<double, 6> last_value_{};
  std::array<int, 6> repeats_{};
  std::array<double, 6> rail_{};  // |value| a flat top was seen at; 0: none yet
};

}  // namespace sinu::est
