// The termios back end and the NMEA stream on one side of a real pty, a
// simulated 5 Hz receiver writing on the other.
#include <gtest/gtest.h>
#include <pty.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "drivers/gps/nmea_stream.hpp"
#include "host_tests/support/nmea_text.hpp"
#include "hal/linux/monotonic_clock.hpp"
#include "hal/linux/termios_serial.hpp"

namespace {

std::string with_checksum(const std::string& body) { return sinu::test::nmea_with_checksum(body) + "\r\n"; }

constexpr int kEpochs = 10;
constexpr auto kPeriod = std::chrono::milliseconds(200);  // 5 Hz

std::string epoch_bytes(int i) {
  char utc[32];
  std::snprintf(utc, sizeof utc, "1015%02d.%02d", 20 + i / 5, (i % 5) * 20);
  char lat[32];
  std::snprintf(lat, sizeof lat, "3024.%05d", 51234 + i);
  return with_checksum(std::string("GNRMC,") + utc + ",A," + lat + ",N,11421.12345,E,10.0,90.0,220326,,,A") +
         with_checksum(std::string("GNGGA,") + utc + "," + lat + ",N,11421.12345,E,1,12,0.8,45.3,M,-2.1,M,,") +
         with_checksum(std::string("GNGST,") + utc + ",1.2,,,,0.9,0.8,1.5");
}

}  // namespace

TEST(SerialPty, FiveHzNmeaThroughTermiosAndParser) {
  int master = -1, slave = -1;
  std::array<char, 128> name{};
  ASSERT_EQ(openpty(&master, &slave, name.data(), nullptr, nullptr), 0);
  ::close(slave);  // the back end opens the tty by name, as on the board
  sinu::hal::TermiosSerialPort port;
  ASSERT_TRUE(port.open(name.data(), 115200)) << port.last_error();

  std::thread receiver([master] {
    auto next = std::chrono::steady_clock::now();
    for (int i = 0; i < kEpochs; ++i) {
      const std::string bytes = epoch_bytes(i);
      // Written in two pieces, as a UART FIFO would deliver them.
      const std::size_t half = bytes.size() / 2;
      EXPECT_EQ(::write(master, bytes.data(), half), static_cast<ssize_t>(half));
      EXPECT_EQ(::write(master, bytes.data() + half, bytes.size() - half), static_cast<ssize_t>(bytes.size() - half));
      next += kPeriod;
      std::this_thread::sleep_until(next);
    }
  });

  sinu::drivers::NmeaStream stream;
  sinu::drivers::GpsFix fix;
  std::vector<sinu::drivers::GpsFix> fixes;
  std::array<std::uint8_t, 64> buffer{};
  const auto deadline = std::chrono::steady_clock::now() + kPeriod * (kEpochs + 5);
  // Every epoch is out as soon as it is complete: its cycle-ending sentence
  // (GST, learned from the first epoch's end) closes it.
  while (fixes.size() < static_cast<std::size_t>(kEpochs) && std::chrono::steady_clock::now() < deadline) {
    const auto r = port.read(buffer, 50'000'000);  // 50 ms poll
    ASSERT_EQ(r.status, sinu::hal::SerialStatus::Ok) << port.last_error();
    for (std::size_t i = 0; i < r.bytes; ++i)
      if (stream.push(static_cast<char>(buffer[i]), sinu::hal::ns_to_s(r.time_ns), fix)) fixes.push_back(fix);
  }
  receiver.join();
  ASSERT_EQ(fixes.size(), static_cast<std::size_t>(kEpochs));
  const auto c = stream.counters();
  EXPECT_EQ(c.sentences.good, 3u * kEpochs);
  EXPECT_EQ(c.sentences.corrupt(), 0u);
  EXPECT_EQ(c.framing.noise_bytes, 0u);
  for (std::size_t i = 0; i < fixes.size(); ++i) {
    SCOPED_TRACE(i);
    const int k = static_cast<int>(i);
    EXPECT_EQ(fixes[i].utc_ms, (10 * 3600 + 15 * 60 + 20) * 1000 + k * 200);
    EXPECT_NEAR(*fixes[i].lat_deg, 30.0 + (24.51234 + k * 1e-5) / 60.0, 1e-12);
    EXPECT_DOUBLE_EQ(*fixes[i].sigma_alt_m, 1.5);
    if (i > 0) {
      // Arrival times come from CLOCK_MONOTONIC at read(); the writer sleeps
      // 200 ms. A loaded CI machine may delay either side: allow +-100 ms.
      EXPECT_NEAR(fixes[i].arrival_s - fixes[i - 1].arrival_s, 0.2, 0.1);
    }
  }
  ::close(master);
}
