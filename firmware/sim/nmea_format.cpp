#include "firmware/sim/nmea_format.hpp"

#include <cmath>
#include <cstdio>

namespace sinu::sim {

namespace {
constexpr char kHex[] = "0123456789ABCDEF";
std::size_t clamp_written(int n, std::size_t cap) {
  return n < 0 ? 0 : std::min(static_cast<std::size_t>(n), cap - 1);
}
}  // namespace

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
  return clamp_written(n, buf.size());
}

std::size_t format_utc(std::span<char> buf, double utc_s) {
  const long long cs = std::llround(utc_s * 100.0) % (86400LL * 100);
  const int n = std::snprintf(buf.data(), buf.size(), "%02lld%02lld%02lld.%02lld", cs / 360000, cs / 6000 % 60,
                              cs / 100 % 60, cs % 100);
  return clamp_written(n, buf.size());
}

std::size_t corrupt_sentence(std::span<char> buf, std::size_t len, Rng& rng) {
  std::size_t star = len;
  for (std::size_t i = 0; i < len; ++i)
    if (buf[i] == '*') star = i;
  switch (rng.below(3)) {
    case 0: {  // one character replaced: the checksum no longer matches
      const std::size_t i = 1 + rng.below(star - 1);
      char c = buf[i];
      while (c == buf[i] || c == '*' || c == '$' || c == ',') c = static_cast<char>('0' + rng.below(43));
      buf[i] = c;
      return len;
    }
    case 1: {  // cut before the '*': no checksum
      const std::size_t keep = 2 + rng.below(star - 2);
      buf[keep] = '\0';
      return keep;
    }
    default: {  // line noise: printable bytes, no '$'
      const std::size_t n = 10 + rng.below(30);
      for (std::size_t i = 0; i < n; ++i) buf[i] = static_cast<char>('%' + rng.below(90));
      buf[n] = '\0';
      return n;
    }
  }
}

}  // namespace sinu::sim
