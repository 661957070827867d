#pragma once
// The raw HAL recording (docs/recording.md): a 16-byte file header, then
// records, all little-endian:
//   kind u8 | payload_length u16 | t_ns i64 | payload | crc32 u32
// The CRC (IEEE 802.3, as zlib's crc32) covers kind .. payload, so a torn
// last record (power cut, crash) is recognised and dropped, never misread.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "hal/clock.hpp"

namespace sinu::hal::rec {

inline constexpr std::array<char, 8> kMagic = {'S', 'I', 'N', 'U', 'R', 'A', 'W', '\0'};
inline constexpr std::uint16_t kVersion = 1;
inline constexpr std::size_t kFileHeaderSize = 16;  // magic, version u16, reserved u16, reserved u32
inline constexpr std::size_t kRecordHeaderSize = 11;  // kind, length, t_ns
inline constexpr std::size_t kRecordTrailerSize = 4;  // crc32
inline constexpr std::size_t kMaxPayload = 1024;      // longest payload written or accepted

enum class Kind : std::uint8_t {
  I2cRead = 1,    // payload: address, register, status, data[n] (data as returned)
  I2cWrite = 2,   // payload: address, register, status, data[n] (data as sent)
  SerialRx = 3,   // payload: port, bytes[n]; t_ns = when the bytes were read
  SerialTx = 4,   // payload: port, bytes[n]
  GpioEdge = 5,   // payload: line; t_ns = the edge's kernel timestamp
  SerialBaud = 6, // payload: port, baud u32
  EdgeTimeout = 7,// payload: line; t_ns = when the wait for an edge gave up (the loop then polls the IMU)
};
/// One past the largest kind: arrays indexed by kind have this size.
inline constexpr std::size_t kKindEnd = 8;
static_assert(kKindEnd == static_cast<std::size_t>(Kind::EdgeTimeout) + 1, "kKindEnd follows the last kind");

const char* to_string(Kind k);
bool is_known(std::uint8_t kind);

/// A record as read (payload points into the reader's buffer).
struct Record {
  Kind kind{};
  TimeNs t_ns = 0;
  std::span<const std::uint8_t> payload;
};

std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc = 0);

}  // namespace sinu::hal::rec
