#include "estimator/nav/imu_screen.hpp"

#include <cmath>
#include <numbers>

#include "estimator/earth/wgs84.hpp"

namespace sinu::est {

namespace {
// MEMS converters come in a few full scales (ICM-20948: 250-2000 deg/s, 2-16 g;
// BMI088: 3-24 g; ADIS: 125-2000 deg/s; high-g parts 32 g). Elsewhere a short
// flat top is a live signal repeating a code: a quadcopter's 180-deg/s yaw
// spin with one code of noise repeats a value three times in a row every few
// seconds, ten times (0.28^9 = 1e-5 per sample) practically never, so an
// unusual range needs the longer run. 15 % either side leaves room for a
// calibrated unit's scale and bias (a rail at 2000 deg/s may read 1950-2050).
constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kGyroFullScales_deg_s[] = {125.0, 250.0, 500.0, 1000.0, 2000.0, 4000.0};
constexpr double kAccelFullScales_g[] = {2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0, 24.0, 32.0};
constexpr double kFullScaleTolerance = 0.15;

bool near_a_full_scale(double magnitude, bool accel) {
  const auto near = [&](double full_scale) { return std::abs(magnitude / full_scale - 1.0) <= kFullScaleTolerance; };
  if (accel) {
    for (double g : kAccelFullScales_g)
      if (near(g * wgs84::kStandardGravity)) return true;
  } else {
    for (double dps : kGyroFullScales_deg_s)
      if (near(dps * kDegToRad)) return true;
  }
  return false;
}
}  // namespace

void ImuScreen::configure(const ImuScreenConfig& cfg) {
  cfg_ = cfg;
  have_last_ = false;
  repeats_.fill(0);
  rail_.fill(0.0);
}

ScreenVerdict ImuScreen::screen(const ImuSample& raw, std::uint8_t& clipped_axes) {
  clipped_axes = 0;
  if (!std::isfinite(raw.t_s) || !raw.specific_force_b_m_s2.allFinite() || !raw.angular_rate_b_rad_s.allFinite())
    return ScreenVerdict::NonFinite;
  if (have_last_ && !(raw.t_s > last_t_s_)) return ScreenVerdict::NotIncreasing;
  for (std::size_t a = 0; a < 6; ++a) {
    const bool accel = a < 3;
    const auto i = static_cast<Eigen::Index>(a % 3);
    const double v = accel ? raw.specific_force_b_m_s2(i) : raw.angular_rate_b_rad_s(i);
    const double range = accel ? cfg_.accel_range_m_s2 : cfg_.gyro_range_rad_s;
    const double flat_above = accel ? cfg_.flat_top_accel_m_s2 : cfg_.flat_top_rate_rad_s;
    repeats_[a] = (have_last_ && v == last_value_[a] && std::abs(v) > flat_above) ? repeats_[a] + 1 : 0;
    last_value_[a] = v;
    const bool at_range = range > 0.0 && std::abs(v) >= cfg_.clip_fraction * range;
    // A rail is the converter's extreme: a sample beyond it says the flat top
    // was a live signal repeating a code (a 180-deg/s spin with 2 codes of
    // noise, on the independent simulator's quadcopter), not a rail.
    if (std::abs(v) > rail_[a]) rail_[a] = 0.0;
    const int needed = near_a_full_scale(std::abs(v), accel) ? cfg_.flat_top_repeats : cfg_.flat_top_repeats_anywhere;
    const bool flat = repeats_[a] + 1 >= needed;
    if (flat) rail_[a] = std::abs(v);
    const bool at_rail = rail_[a] > 0.0 && std::abs(v) == rail_[a];
    if (at_range || flat || at_rail) clipped_axes |= static_cast<std::uint8_t>(1u << a);
  }
  have_last_ = true;
  last_t_s_ = raw.t_s;
  return ScreenVerdict::Keep;
}

}  // namespace sinu::est
