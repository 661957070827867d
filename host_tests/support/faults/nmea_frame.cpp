#include "host_tests/support/faults/nmea_frame.hpp"

namespace sinu::test::faults {

namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

unsigned char nmea_xor(std::string_view body) {
  unsigned char x = 0;
  for (char c : body) x = static_cast<unsigned char>(x ^ static_cast<unsigned char>(c));
  return x;
}

std::optional<std::string_view> checked_body(std::string_view s) {
  if (s.size() < 4 || s.front() != '$' || s[s.size() - 3] != '*') return std::nullopt;
  const std::string_view body = s.substr(1, s.size() - 4);
  for (char c : body) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u > 0x7e || c == '$' || c == '*') return std::nullopt;
  }
  const int hi = hex_digit(s[s.size() - 2]), lo = hex_digit(s[s.size() - 1]);
  if (hi < 0 || lo < 0 || hi * 16 + lo != nmea_xor(body)) return std::nullopt;
  return body;
}

bool lower_case_checksum(std::string_view s) {
  if (s.size() < 2) return false;
  const auto lower = [](char c) { return c >= 'a' && c <= 'f'; };
  return lower(s[s.size() - 1]) || lower(s[s.size() - 2]);
}

std::string frame_with_checksum(std::string_view body, unsigned char checksum, bool lower_case_hex) {
  const char* digits = lower_case_hex ? "0123456789abcdef" : "0123456789ABCDEF";
  std::string s = "$";
  s += body;
  s += '*';
  s += digits[checksum >> 4];
  s += digits[checksum & 0x0F];
  return s;
}

std::string frame_sentence(std::string_view body, bool lower_case_hex) {
  return frame_with_checksum(body, nmea_xor(body), lower_case_hex);
}

}  // namespace sinu::test::faults
