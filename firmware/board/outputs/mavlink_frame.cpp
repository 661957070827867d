#include "firmware/board/outputs/mavlink_frame.hpp"

#include <algorithm>

#include "firmware/board/outputs/mavlink_crc.hpp"

namespace sinu::board::mavlink {

std::size_t truncated_length(std::span<const std::uint8_t> payload) {
  std::size_t n = payload.size();
  while (n > 1 && payload[n - 1] == 0) --n;
  return n;
}

std::size_t encode_frame(const MessageInfo& info, std::span<const std::uint8_t> payload, const FrameHeader& header,
                         MavlinkFrame& out) {
  out.size = 0;
  if (payload.size() != info.length || payload.empty() || info.id > 0xFFFFFFu) return 0;
  const std::size_t len = truncated_length(payload);
  auto& d = out.data;
  d[0] = kStx;
  d[1] = static_cast<std::uint8_t>(len);
  d[2] = 0;  // incompat_flags: not signed
  d[3] = 0;  // compat_flags
  d[4] = header.sequence;
  d[5] = header.system_id;
  d[6] = header.component_id;
  d[7] = static_cast<std::uint8_t>(info.id & 0xFFu);
  d[8] = static_cast<std::uint8_t>((info.id >> 8) & 0xFFu);
  d[9] = static_cast<std::uint8_t>((info.id >> 16) & 0xFFu);
  std::copy_n(payload.begin(), len, d.begin() + kHeaderBytes);
  const std::size_t body = kHeaderBytes + len;
  std::uint16_t crc = crc_accumulate(std::span<const std::uint8_t>(d.data() + 1, body - 1), kCrcSeed);
  crc = crc_accumulate(info.crc_extra, crc);
  d[body] = static_cast<std::uint8_t>(crc & 0xFFu);
  d[body + 1] = static_cast<std::uint8_t>(crc >> 8);
  out.size = body + kChecksumBytes;
  return out.size;
}

}  // namespace sinu::board::mavlink
