#pragma once
// Set-up commands that put a GPS receiver into 5 Hz (or any rate) and a
// faster baud rate. Each builder fills a caller's buffer and returns the
// bytes used (0 if the buffer is too small). Nothing allocates.
//   u-blox M8 and older: UBX-CFG-RATE (0x06 0x08), UBX-CFG-PRT (0x06 0x00)
//   u-blox M9/M10/F9:    UBX-CFG-VALSET (0x06 0x8A) with CFG-RATE-MEAS and
//                        CFG-UART1-BAUDRATE
//   MediaTek (MT3329/3339): $PMTK220 (fix interval), $PMTK251 (baud)
// Frames follow the u-blox interface descriptions (UBX checksum: 8-bit
// Fletcher over class .. payload) and the MTK NMEA packet manual.
#include <cstddef>
#include <cstdint>
#include <span>

namespace sinu::drivers::gps_setup {

inline constexpr std::uint32_t kKeyCfgRateMeas = 0x30210001;      // U2, measurement period [ms]
inline constexpr std::uint32_t kKeyCfgUart1Baudrate = 0x40520001; // U4, [bit/s]
enum ValsetLayer : std::uint8_t { kRam = 0x01, kBbr = 0x02, kFlash = 0x04 };

/// A UBX frame: B5 62, class, id, length (LE), payload, CK_A, CK_B.
std::size_t ubx_frame(std::uint8_t cls, std::uint8_t id, std::span<const std::uint8_t> payload,
                      std::span<std::uint8_t> out);
/// UBX-CFG-RATE: measurement period, one navigation solution per measurement, GPS time.
std::size_t ubx_cfg_rate(std::uint16_t period_ms, std::span<std::uint8_t> out);
/// UBX-CFG-PRT for UART1: 8N1 at `baud`, UBX+NMEA+RTCM in, UBX+NMEA out.
std::size_t ubx_cfg_prt_uart1(std::uint32_t baud, std::span<std::uint8_t> out);
/// UBX-CFG-VALSET with one U2 and one U4 item: rate period and UART1 baud.
std::size_t ubx_valset_rate_baud(std::uint16_t period_ms, std::uint32_t baud, std::uint8_t layers,
                                 std::span<std::uint8_t> out);
/// "$PMTK220,<period_ms>*hh\r\n".
std::size_t pmtk220_fix_interval(std::uint32_t period_ms, std::span<std::uint8_t> out);
/// "$PMTK251,<baud>*hh\r\n".
std::size_t pmtk251_baud(std::uint32_t baud, std::span<std::uint8_t> out);

}  // namespace sinu::drivers::gps_setup
