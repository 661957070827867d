#pragma once
// MAVLink 2 framing (mavlink.io, "Packet Serialization"), unsigned:
//   0     STX 0xFD
//   1     len: payload bytes after trailing-zero truncation (at least 1)
//   2, 3  incompat_flags 0 (no signature), compat_flags 0
//   4     seq, 5 sysid, 6 compid
//   7..9  msgid, 24 bits little-endian
//   10..  payload (len bytes)
//   +2    CRC-16/MCRF4XX over bytes 1..9+len, then the message's CRC_EXTRA;
//         low byte first.
// Fixed-size buffer: no allocation.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "firmware/board/outputs/mavlink_message_def.hpp"

namespace sinu::board::mavlink {

inline constexpr std::uint8_t kStx = 0xFD;
inline constexpr std::size_t kHeaderBytes = 10;       // STX to msgid
inline constexpr std::size_t kChecksumBytes = 2;
inline constexpr std::size_t kMaxFrameBytes = 280;    // a signed frame with a full payload (the spec's maximum)

struct FrameHeader {
  std::uint8_t sequence = 0;
  std::uint8_t system_id = 1;
  std::uint8_t component_id = 191;  // MAV_COMP_ID_ONBOARD_COMPUTER
};

struct MavlinkFrame {
  std::array<std::uint8_t, kMaxFrameBytes> data{};
  std::size_t size = 0;  // bytes of the frame in `data` (0: none)
  std::span<const std::uint8_t> bytes() const { return {data.data(), size}; }
};

/// Payload length after MAVLink 2 truncation: trailing zero bytes dropped,
/// the first byte always kept.
std::size_t truncated_length(std::span<const std::uint8_t> payload);

/// Frames `payload` (the message's full, untruncated payload: info.length
/// bytes) into `out`. Returns the frame size, 0 if the payload length is not
/// the message's or the id does not fit 24 bits (then `out` is empty).
std::size_t encode_frame(const MessageInfo& info, std::span<const std::uint8_t> payload, const FrameHeader& header,
                         MavlinkFrame& out);

}  // namespace sinu::board::mavlink
