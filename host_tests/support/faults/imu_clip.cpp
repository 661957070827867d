#include "host_tests/support/faults/imu_clip.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>

#include "host_tests/support/faults/text_lines.hpp"

namespace sinu::test::faults {

namespace {

constexpr std::size_t kAccelX = 1, kGyroX = 4;  // imu.csv: t,ax,ay,az,gx,gy,gz,...

/// What one axis reads while clipping.
double clipped_value(double v, double t, std::size_t axis, int direction, double fs, const ImuClip& c) {
  if (c.mode == ClipMode::Pegged) return direction > 0 ? fs : -fs;
  const double phase = 2.0 * std::numbers::pi * c.vibration_hz * (t - c.start_s) + c.vibration_phase_rad[axis];
  return std::clamp(v + c.vibration_amplitude_fs * fs * std::sin(phase), -fs, fs);
}

bool clip_triad(std::vector<std::string>& fields, std::size_t first, double t, const std::array<int, 3>& direction,
                double fs, const ImuClip& c) {
  bool changed = false;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const std::size_t i = first + axis;
    if (direction[axis] == 0 || i >= fields.size()) continue;
    const auto v = leading_number(fields[i]);
    if (!v) continue;
    const double clipped = clipped_value(*v, t, axis, direction[axis], fs, c);
    if (clipped == *v) continue;  // the recorded text stays, whatever its form
    fields[i] = shortest_text(clipped);
    changed = true;
  }
  return changed;
}

}  // namespace

std::string shortest_text(double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc{} ? std::string(buf, end) : std::string{};
}

bool clip_imu_row(std::vector<std::string>& fields, double t, const ImuClip& c) {
  bool changed = clip_triad(fields, kAccelX, t, c.accel_direction, c.accel_full_scale_m_s2, c);
  if (c.gyro_full_scale_rad_s > 0.0)
    changed = clip_triad(fields, kGyroX, t, c.gyro_direction, c.gyro_full_scale_rad_s, c) || changed;
  return changed;
}

}  // namespace sinu::test::faults
