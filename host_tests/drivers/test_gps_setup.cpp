// GPS set-up commands, byte for byte against frames published for these
// receivers (u-blox M8 protocol description examples as widely quoted, the
// MediaTek PMTK packet manual / Adafruit GPS library constants).
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "drivers/gps/gps_setup.hpp"
#include "drivers/gps/nmea_sentence.hpp"

namespace gs = sinu::drivers::gps_setup;

namespace {
std::vector<std::uint8_t> bytes(std::size_t (*f)(std::uint32_t, std::span<std::uint8_t>), std::uint32_t v) {
  std::array<std::uint8_t, 64> buf{};
  const std::size_t n = f(v, buf);
  return {buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(n)};
}
std::string text(const std::vector<std::uint8_t>& b) { return {b.begin(), b.end()}; }

// Fletcher-8 as the UBX protocol description defines it, written out again
// here so the test does not reuse the code under test.
std::pair<std::uint8_t, std::uint8_t> fletcher(const std::vector<std::uint8_t>& frame) {
  unsigned a = 0, b = 0;
  for (std::size_t i = 2; i + 2 < frame.size(); ++i) {
    a = (a + frame[i]) & 0xFFu;
    b = (b + a) & 0xFFu;
  }
  return {static_cast<std::uint8_t>(a), static_cast<std::uint8_t>(b)};
}
}  // namespace

TEST(GpsSetup, MediaTekFiveHzAndBaud) {
  EXPECT_EQ(text(bytes(gs::pmtk220_fix_interval, 200)), "$PMTK220,200*2C\r\n");  // PMTK_SET_NMEA_UPDATE_5HZ
  EXPECT_EQ(text(bytes(gs::pmtk220_fix_interval, 1000)), "$PMTK220,1000*1F\r\n"); // 1 Hz, the manual's example
  EXPECT_EQ(text(bytes(gs::pmtk251_baud, 115200)), "$PMTK251,115200*1F\r\n");
  EXPECT_EQ(text(bytes(gs::pmtk251_baud, 38400)), "$PMTK251,38400*27\r\n");
  // And our own NMEA checker accepts them.
  const std::string s = text(bytes(gs::pmtk251_baud, 57600));
  EXPECT_EQ(sinu::drivers::check_sentence(s.substr(0, s.size() - 2)), sinu::drivers::SentenceCheck::Ok);
}

TEST(GpsSetup, UbxCfgRateFiveHz) {
  std::array<std::uint8_t, 32> buf{};
  const std::size_t n = gs::ubx_cfg_rate(200, buf);
  const std::vector<std::uint8_t> expected = {0xB5, 0x62, 0x06, 0x08, 0x06, 0x00, 0xC8, 0x00,
                                              0x01, 0x00, 0x01, 0x00, 0xDE, 0x6A};
  EXPECT_EQ(std::vector<std::uint8_t>(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(n)), expected);
}

TEST(GpsSetup, UbxCfgPrtUart1At115200) {
  std::array<std::uint8_t, 32> buf{};
  const std::size_t n = gs::ubx_cfg_prt_uart1(115200, buf);
  const std::vector<std::uint8_t> expected = {0xB5, 0x62, 0x06, 0x00, 0x14, 0x00, 0x01, 0x00, 0x00, 0x00,
                                              0xD0, 0x08, 0x00, 0x00, 0x00, 0xC2, 0x01, 0x00, 0x07, 0x00,
                                              0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC0, 0x7E};
  EXPECT_EQ(std::vector<std::uint8_t>(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(n)), expected);
}

TEST(GpsSetup, UbxValsetCarriesTheDocumentedKeysAndChecksum) {
  std::array<std::uint8_t, 64> buf{};
  const std::size_t n = gs::ubx_valset_rate_baud(200, 230400, gs::kRam | gs::kBbr, buf);
  const std::vector<std::uint8_t> f(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(n));
  ASSERT_EQ(f.size(), 8u + 18u);
  EXPECT_EQ(f[2], 0x06);
  EXPECT_EQ(f[3], 0x8A);  // UBX-CFG-VALSET
  EXPECT_EQ(f[4], 18);
  EXPECT_EQ(f[7], 0x03);  // layers RAM | BBR
  // CFG-RATE-MEAS = 0x30210001 (size code 3: two bytes), little-endian, then 200 ms.
  EXPECT_EQ(std::vector<std::uint8_t>(f.begin() + 10, f.begin() + 16),
            (std::vector<std::uint8_t>{0x01, 0x00, 0x21, 0x30, 0xC8, 0x00}));
  // CFG-UART1-BAUDRATE = 0x40520001 (size code 4: four bytes), then 230400 = 0x00038400.
  EXPECT_EQ(std::vector<std::uint8_t>(f.begin() + 16, f.begin() + 24),
            (std::vector<std::uint8_t>{0x01, 0x00, 0x52, 0x40, 0x00, 0x84, 0x03, 0x00}));
  const auto [a, b] = fletcher(f);
  EXPECT_EQ(f[24], a);
  EXPECT_EQ(f[25], b);
}

TEST(GpsSetup, RefusesAShortBuffer) {
  std::array<std::uint8_t, 10> small{};
  EXPECT_EQ(gs::ubx_cfg_rate(200, small), 0u);
  EXPECT_EQ(gs::pmtk251_baud(115200, small), 0u);
}
