#include "firmware/board/outputs/nmea_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sinu::board {

namespace {
constexpr char kHex[] = "0123456789ABCDEF";
}  // namespace

std::size_t written_length(int n, std::size_t capacity) {
  return n < 0 ? 0 : std::min(static_cast<std::size_t>(n), capacity - 1);
}

std::size_t append_checksum(std::span<char> buf, std::size_t len) {
  unsigned char x = 0;
  for (std::size_t i = 1; i < len; ++i) x = static_cast<unsigned char>(x ^ static_cast<unsigned char>(buf[i]));
  buf[len] = '*';
  buf[len + 1] = kHex[x >> 4];
  buf[len + 2] = kHex[x & 0x0F];
  buf[len + 3] = '\0';
  return len + 3;
}

std::size_t format_angle(std::span<char> buf, double deg, int degree_digits, char positive, char negative) {
  constexpr long long kUnitsPerMinute = 1000000;  // 6 decimals of a minute: 1.9 mm of latitude
  const long long units = std::llround(std::abs(deg) * 60.0 * kUnitsPerMinute);
  const long long whole_deg = units / (60 * kUnitsPerMinute);
  const long long rem = units % (60 * kUnitsPerMinute);
  const int n = std::snprintf(buf.data(), buf.size(), "%0*lld%02lld.%06lld,%c", degree_digits, whole_deg,
                              rem / kUnitsPerMinute, rem % kUnitsPerMinute, deg < 0.0 ? negative : positive);
  return written_length(n, buf.size());
}

std::size_t format_time_of_day(std::span<char> buf, long long ticks, int decimals) {
  long long per_second = 1;
  for (int i = 0; i < decimals; ++i) per_second *= 10;
  const long long s = ticks / per_second;
  int n = std::snprintf(buf.data(), buf.size(), "%02lld%02lld%02lld", s / 3600, s / 60 % 60, s % 60);
  if (decimals > 0 && n > 0 && static_cast<std::size_t>(n) < buf.size())
    n += std::snprintf(buf.data() + n, buf.size() - static_cast<std::size_t>(n), ".%0*lld", decimals,
                       ticks % per_second);
  return written_length(n, buf.size());
}

std::size_t format_fixed(std::span<char> buf, double value, int decimals, double max_abs) {
  if (!std::isfinite(value) || std::abs(value) > max_abs) {
    if (!buf.empty()) buf[0] = '\0';
    return 0;
  }
  return written_length(std::snprintf(buf.data(), buf.size(), "%.*f", decimals, value), buf.size());
}

}  // namespace sinu::board
