#pragma once
// Builds NMEA test sentences: "$" + body + "*hh" (upper-case hex).
#include <cstdio>
#include <string>

namespace sinu::test {

inline std::string nmea_with_checksum(const std::string& body) {
  unsigned sum = 0;
  for (char c : body) sum ^= static_cast<unsigned char>(c);
  char hex[4];
  std::snprintf(hex, sizeof hex, "%02X", sum);
  return "$" + body + "*" + hex;
}

}  // namespace sinu::test
