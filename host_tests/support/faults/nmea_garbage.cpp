#include "host_tests/support/faults/nmea_garbage.hpp"

#include <algorithm>

#include "host_tests/support/faults/nmea_frame.hpp"

namespace sinu::test::faults {

namespace {

/// The original up to its first '*' (all of it if none), at most `limit` bytes.
std::string_view before_star(std::string_view s, std::size_t limit) {
  return s.substr(0, std::min(s.find('*'), limit));
}

}  // namespace

char GarbageGenerator::random_byte() {
  while (true) {
    const auto c = static_cast<char>(static_cast<unsigned char>(below(256)));
    if (c != '\n' && c != '\r') return c;
  }
}

char GarbageGenerator::random_non_printable() {
  while (true) {
    const char c = random_byte();
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u > 0x7e) return c;
  }
}

void GarbageGenerator::force_non_printable(std::string& s) { s[below(s.size())] = random_non_printable(); }

std::string GarbageGenerator::noise() {
  std::string s(8 + below(113), ' ');
  for (auto& c : s) c = below(5) == 0 ? random_byte() : static_cast<char>(0x20 + below(0x5f));
  force_non_printable(s);
  return s;
}

std::string GarbageGenerator::binary() {
  std::string s(16 + below(185), ' ');
  for (auto& c : s) c = random_byte();
  force_non_printable(s);
  return s;
}

std::string GarbageGenerator::truncated(std::string_view original) {
  // Keep fewer bytes than the part before '*': no '*' survives.
  const std::string_view head = before_star(original, kMaxGarbageBytes);
  if (head.size() < 2) return noise();
  return std::string(head.substr(0, 1 + below(head.size() - 1)));
}

std::string GarbageGenerator::wrong_checksum(std::string_view original) {
  const std::string_view head = before_star(original, kMaxGarbageBytes - 3);
  if (head.size() < 2 || head.front() != '$') return noise();
  const std::string_view body = head.substr(1);
  const auto wrong = static_cast<unsigned char>(nmea_xor(body) ^ (1 + below(255)));
  return frame_with_checksum(body, wrong, false);
}

std::string GarbageGenerator::next(std::string_view original) {
  std::string s;
  switch (below(4)) {
    case 0: s = noise(); break;
    case 1: s = truncated(original); break;
    case 2: s = wrong_checksum(original); break;
    default: s = binary(); break;
  }
  // A CR inside the original (not before its LF) must not survive either.
  std::replace(s.begin(), s.end(), '\r', '\x7f');
  return s;
}

}  // namespace sinu::test::faults
