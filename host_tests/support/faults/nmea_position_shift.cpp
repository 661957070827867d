#include "host_tests/support/faults/nmea_position_shift.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "host_tests/support/faults/nmea_angle.hpp"
#include "host_tests/support/faults/nmea_frame.hpp"
#include "host_tests/support/faults/text_lines.hpp"

namespace sinu::test::faults {

namespace {

constexpr double kA = 6378137.0, kF = 1.0 / 298.257223563, kE2 = kF * (2.0 - kF);  // WGS-84
constexpr double kRadToDeg = 180.0 / std::numbers::pi;

double meridian_radius_m(double lat_rad) {
  const double s = std::sin(lat_rad);
  return kA * (1.0 - kE2) / std::pow(1.0 - kE2 * s * s, 1.5);
}
double transverse_radius_m(double lat_rad) {
  const double s = std::sin(lat_rad);
  return kA / std::sqrt(1.0 - kE2 * s * s);
}

/// Where a sentence type keeps its fields (index 0 is the address).
struct Layout {
  std::size_t lat, lon, alt;  // alt 0: none
};

std::optional<Layout> layout_of(std::string_view address) {
  if (address.size() < 3 || address.front() == 'P') return std::nullopt;  // proprietary
  const std::string_view type = address.substr(2);
  if (type == "GGA") return Layout{2, 4, 9};
  if (type == "RMC") return Layout{3, 5, 0};
  if (type == "GLL") return Layout{1, 3, 0};
  return std::nullopt;
}

/// Moves fields[lat..lat+3] north/east; false if the latitude is unreadable.
bool shift_horizontal(std::vector<std::string>& f, const Layout& at, double north_m, double east_m) {
  if (north_m == 0.0 && east_m == 0.0) return false;
  if (f.size() <= at.lon + 1) return false;
  const auto lat = parse_angle(f[at.lat], f[at.lat + 1], kLatitude);
  if (!lat) return false;
  const double lat_rad = lat->value / kRadToDeg;
  bool changed = false;
  if (north_m != 0.0) {
    const double moved = std::clamp(lat->value + north_m / meridian_radius_m(lat_rad) * kRadToDeg, -90.0, 90.0);
    format_angle(moved, lat->decimals, kLatitude, f[at.lat], f[at.lat + 1]);
    changed = true;
  }
  const auto lon = parse_angle(f[at.lon], f[at.lon + 1], kLongitude);
  const double east_radius = transverse_radius_m(lat_rad) * std::cos(lat_rad);
  if (east_m != 0.0 && lon && east_radius > 1.0) {
    double moved = lon->value + east_m / east_radius * kRadToDeg;
    if (moved > 180.0) moved -= 360.0;
    if (moved < -180.0) moved += 360.0;
    format_angle(moved, lon->decimals, kLongitude, f[at.lon], f[at.lon + 1]);
    changed = true;
  }
  return changed;
}

/// Lowers GGA's altitude above MSL by down_m; false if absent or unreadable.
bool shift_altitude(std::vector<std::string>& f, const Layout& at, double down_m) {
  if (at.alt == 0 || down_m == 0.0 || f.size() <= at.alt) return false;
  const auto alt = parse_plain_decimal(f[at.alt]);
  if (!alt) return false;
  f[at.alt] = format_plain_decimal(alt->value - down_m, alt->decimals);
  return true;
}

}  // namespace

std::optional<std::string> shift_position(std::string_view sentence, const std::array<double, 3>& offset_ned_m) {
  const auto body = checked_body(sentence);
  if (!body) return std::nullopt;  // corrupt sentences stay corrupt
  std::vector<std::string> f = split_fields(*body);
  const auto at = layout_of(f[0]);
  if (!at) return std::nullopt;
  const bool moved = shift_horizontal(f, *at, offset_ned_m[0], offset_ned_m[1]);
  const bool lowered = shift_altitude(f, *at, offset_ned_m[2]);
  if (!moved && !lowered) return std::nullopt;
  return frame_sentence(join_fields(f), lower_case_checksum(sentence));
}

}  // namespace sinu::test::faults
