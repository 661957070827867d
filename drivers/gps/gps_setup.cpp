#include "drivers/gps/gps_setup.hpp"

#include <array>
#include <cstdio>
#include <cstring>

namespace sinu::drivers::gps_setup {

namespace {

constexpr std::uint8_t kClassCfg = 0x06;
constexpr std::uint8_t kIdPrt = 0x00, kIdRate = 0x08, kIdValset = 0x8A;
constexpr std::size_t kUbxOverhead = 8;  // sync 2, class, id, length 2, checksum 2

template <std::size_t N>
void put_le(std::array<std::uint8_t, N>& a, std::size_t at, std::uint32_t v, std::size_t bytes) {
  for (std::size_t i = 0; i < bytes; ++i) a[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}

std::size_t nmea_command(const char* body_format, std::uint32_t value, std::span<std::uint8_t> out) {
  std::array<char, 48> body{};
  const int n = std::snprintf(body.data(), body.size(), body_format, value);
  if (n <= 0 || static_cast<std::size_t>(n) >= body.size()) return 0;
  unsigned sum = 0;
  for (int i = 0; i < n; ++i) sum ^= static_cast<unsigned char>(body[static_cast<std::size_t>(i)]);
  std::array<char, 64> line{};
  const int total = std::snprintf(line.data(), line.size(), "$%s*%02X\r\n", body.data(), sum);
  if (total <= 0 || static_cast<std::size_t>(total) > out.size()) return 0;
  std::memcpy(out.data(), line.data(), static_cast<std::size_t>(total));
  return static_cast<std::size_t>(total);
}

}  // namespace

std::size_t ubx_frame(std::uint8_t cls, std::uint8_t id, std::span<const std::uint8_t> payload,
                      std::span<std::uint8_t> out) {
  const std::size_t total = payload.size() + kUbxOverhead;
  if (out.size() < total || payload.size() > 0xFFFF) return 0;
  out[0] = 0xB5;
  out[1] = 0x62;
  out[2] = cls;
  out[3] = id;
  out[4] = static_cast<std::uint8_t>(payload.size());
  out[5] = static_cast<std::uint8_t>(payload.size() >> 8);
  if (!payload.empty()) std::memcpy(out.data() + 6, payload.data(), payload.size());
  std::uint8_t ck_a = 0, ck_b = 0;
  for (std::size_t i = 2; i < 6 + payload.size(); ++i) {
    ck_a = static_cast<std::uint8_t>(ck_a + out[i]);
    ck_b = static_cast<std::uint8_t>(ck_b + ck_a);
  }
  out[6 + payload.size()] = ck_a;
  out[7 + payload.size()] = ck_b;
  return total;
}

std::size_t ubx_cfg_rate(std::uint16_t period_ms, std::span<std::uint8_t> out) {
  std::array<std::uint8_t, 6> p{};
  put_le(p, 0, period_ms, 2);
  put_le(p, 2, 1, 2);  // navRate: one solution per measurement
  put_le(p, 4, 1, 2);  // timeRef: GPS time
  return ubx_frame(kClassCfg, kIdRate, p, out);
}

std::size_t ubx_cfg_prt_uart1(std::uint32_t baud, std::span<std::uint8_t> out) {
  std::array<std::uint8_t, 20> p{};
  p[0] = 1;                    // portID: UART1
  put_le(p, 4, 0x000008D0, 4); // mode: 8 data bits, no parity, 1 stop bit
  put_le(p, 8, baud, 4);
  put_le(p, 12, 0x0007, 2);    // inProtoMask: UBX, NMEA, RTCM2
  put_le(p, 14, 0x0003, 2);    // outProtoMask: UBX, NMEA
  return ubx_frame(kClassCfg, kIdPrt, p, out);
}

std::size_t ubx_valset_rate_baud(std::uint16_t period_ms, std::uint32_t baud, std::uint8_t layers,
                                 std::span<std::uint8_t> out) {
  std::array<std::uint8_t, 4 + 6 + 8> p{};
  p[0] = 0;  // version
  p[1] = layers;
  put_le(p, 4, kKeyCfgRateMeas, 4);
  put_le(p, 8, period_ms, 2);
  put_le(p, 10, kKeyCfgUart1Baudrate, 4);
  put_le(p, 14, baud, 4);
  return ubx_frame(kClassCfg, kIdValset, p, out);
}

std::size_t pmtk220_fix_interval(std::uint32_t period_ms, std::span<std::uint8_t> out) {
  return nmea_command("PMTK220,%u", period_ms, out);
}

std::size_t pmtk251_baud(std::uint32_t baud, std::span<std::uint8_t> out) {
  return nmea_command("PMTK251,%u", baud, out);
}

}  // namespace sinu::drivers::gps_setup
