#pragma once
// CRC-16/MCRF4XX, the checksum of MAVLink frames (mavlink.io, "Packet
// Serialization" > Checksum): the reflected CCITT polynomial x^16+x^12+x^5+1,
// seeded 0xFFFF, no final XOR. The same CRC folds the generator's text of a
// message definition into its CRC_EXTRA byte, so it is constexpr.
#include <cstdint>
#include <span>
#include <string_view>

namespace sinu::board::mavlink {

inline constexpr std::uint16_t kCrcSeed = 0xFFFF;

/// Folds one byte into `crc`. Byte-wise form of the reflected polynomial
/// 0x8408: the byte XOR the low CRC byte, spread over the polynomial's taps.
constexpr std::uint16_t crc_accumulate(std::uint8_t byte, std::uint16_t crc) {
  auto t = static_cast<std::uint8_t>(byte ^ static_cast<std::uint8_t>(crc & 0xFF));
  t = static_cast<std::uint8_t>(t ^ static_cast<std::uint8_t>(t << 4));
  return static_cast<std::uint16_t>((crc >> 8) ^ (t << 8) ^ (t << 3) ^ (t >> 4));
}

constexpr std::uint16_t crc_accumulate(std::span<const std::uint8_t> bytes, std::uint16_t crc) {
  for (const std::uint8_t b : bytes) crc = crc_accumulate(b, crc);
  return crc;
}

constexpr std::uint16_t crc_accumulate(std::string_view text, std::uint16_t crc) {
  for (const char c : text) crc = crc_accumulate(static_cast<std::uint8_t>(c), crc);
  return crc;
}

}  // namespace sinu::board::mavlink
