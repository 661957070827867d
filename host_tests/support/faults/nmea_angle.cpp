#include "host_tests/support/faults/nmea_angle.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace sinu::test::faults {

namespace {

constexpr int kMaxDecimals = 9;  // 180 deg * 60 * 1e9 units still fits an int64

bool all_digits(std::string_view s) {
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

long long pow10(int n) {
  long long p = 1;
  while (n-- > 0) p *= 10;
  return p;
}

/// Non-negative v in at least `width` digits.
std::string zero_padded(long long v, int width) {
  std::string s = std::to_string(v);
  if (s.size() < static_cast<std::size_t>(width)) s.insert(0, static_cast<std::size_t>(width) - s.size(), '0');
  return s;
}

double to_double(std::string_view s) { return std::strtod(std::string(s).c_str(), nullptr); }

}  // namespace

std::optional<DecimalValue> parse_angle(std::string_view field, std::string_view hemi, AngleFormat f) {
  if (hemi.size() != 1 || (hemi[0] != f.positive && hemi[0] != f.negative)) return std::nullopt;
  const std::size_t dot = field.find('.');
  const std::string_view whole = field.substr(0, dot);
  const std::string_view frac = dot == std::string_view::npos ? std::string_view{} : field.substr(dot + 1);
  const auto int_len = static_cast<std::size_t>(f.degree_digits + 2);
  if (whole.size() != int_len || !all_digits(whole) || !all_digits(frac) || frac.size() > kMaxDecimals)
    return std::nullopt;
  const double degrees = to_double(whole.substr(0, int_len - 2));
  const double minutes = to_double(field.substr(int_len - 2));
  if (minutes >= 60.0) return std::nullopt;
  const double v = degrees + minutes / 60.0;
  return DecimalValue{hemi[0] == f.negative ? -v : v, static_cast<int>(frac.size())};
}

void format_angle(double deg, int decimals, AngleFormat f, std::string& field, std::string& hemisphere) {
  const long long per_minute = pow10(decimals);
  const long long units = std::llround(std::abs(deg) * 60.0 * static_cast<double>(per_minute));
  const long long whole_deg = units / (60 * per_minute), rem = units % (60 * per_minute);
  field = zero_padded(whole_deg, f.degree_digits) + zero_padded(rem / per_minute, 2);
  if (decimals > 0) {
    field += '.';
    field += zero_padded(rem % per_minute, decimals);
  }
  hemisphere = std::string(1, deg < 0.0 && units != 0 ? f.negative : f.positive);
}

std::optional<DecimalValue> parse_plain_decimal(std::string_view field) {
  std::string_view digits = field;
  if (!digits.empty() && (digits[0] == '+' || digits[0] == '-')) digits.remove_prefix(1);
  const std::size_t dot = digits.find('.');
  const std::string_view whole = digits.substr(0, dot);
  const std::string_view frac = dot == std::string_view::npos ? std::string_view{} : digits.substr(dot + 1);
  if (whole.empty() || !all_digits(whole) || !all_digits(frac) || frac.size() > kMaxDecimals) return std::nullopt;
  return DecimalValue{to_double(field), static_cast<int>(frac.size())};
}

std::string format_plain_decimal(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  std::string s = buf;
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);  // "-0.000"
  return s;
}

}  // namespace sinu::test::faults
