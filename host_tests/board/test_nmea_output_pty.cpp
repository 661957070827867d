// The NMEA output on a real serial device: NmeaOutput writes through the
// termios back end (raw 8N1, as on the board) into one side of a pty; the
// other side must receive the very bytes the sentence writers produce, and
// the project's NMEA stream must decode them to the solutions' values.
#include <gtest/gtest.h>
#include <poll.h>
#include <pty.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <string>

#include "firmware/board/outputs/nmea_output.hpp"
#include "hal/linux/termios_serial.hpp"
#include "host_tests/board/nmea_output_cases.hpp"

namespace {

namespace t = sinu::test;

/// Reads from the pty's master side until `want` bytes arrived or 1 s passed.
std::string read_master(int fd, std::size_t want) {
  std::string got;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  std::array<char, 512> buf{};
  while (got.size() < want && std::chrono::steady_clock::now() < deadline) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 50) <= 0) continue;
    const ssize_t n = ::read(fd, buf.data(), buf.size());
    if (n > 0) got.append(buf.data(), static_cast<std::size_t>(n));
  }
  return got;
}

}  // namespace

TEST(NmeaOutputPty, SentencesArriveIntactAndParseToTheSolution) {
  int master = -1, slave = -1;
  std::array<char, 128> name{};
  ASSERT_EQ(openpty(&master, &slave, name.data(), nullptr, nullptr), 0);
  sinu::hal::TermiosSerialPort port;
  ASSERT_TRUE(port.open(name.data(), 115200)) << port.last_error();
  ::close(slave);  // the port holds its own descriptor of the tty, as on the board

  sinu::board::NmeaOutput out(port, {sinu::board::NmeaTalker::GN, 5.0});
  const auto cases = t::hemisphere_cases();
  std::string expected, received;
  std::array<char, sinu::board::kNmeaEpochMax> buf{};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    sinu::board::NavSolution n = cases[i];
    n.t_s = 10.0 + 0.2 * static_cast<double>(i);  // one epoch per 5 Hz period
    const std::uint64_t before = out.counters().bytes;
    ASSERT_TRUE(out.offer(n)) << port.last_error();
    ASSERT_EQ(out.counters().epochs, i + 1);
    expected.append(buf.data(), sinu::board::write_nmea_epoch(n, sinu::board::NmeaTalker::GN, buf));
    received += read_master(master, static_cast<std::size_t>(out.counters().bytes - before));
  }
  ::close(master);
  EXPECT_EQ(received, expected);  // byte for byte: no CR/LF translation, nothing lost

  const t::Decoded d = t::decode_with_project_parser(received);
  EXPECT_EQ(d.counters.sentences.good, 3 * cases.size());
  EXPECT_EQ(d.counters.sentences.corrupt(), 0u);
  EXPECT_EQ(d.counters.framing.noise_bytes, 0u);
  ASSERT_EQ(d.fixes.size(), cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(i);
    t::expect_fix_matches(d.fixes[i], cases[i]);
  }
}
