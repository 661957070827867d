// MavlinkOutput end to end: over UDP on loopback (rates, sequence numbers,
// one frame per datagram), over a pty through the termios back end (the same
// bytes), and without a heap allocation per message.
#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <pty.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <map>
#include <vector>

#include "firmware/board/outputs/mavlink_messages.hpp"
#include "firmware/board/outputs/mavlink_output.hpp"
#include "hal/linux/termios_serial.hpp"
#include "hal/linux/udp_socket.hpp"
#include "host_tests/board/mavlink_reference.hpp"
#include "host_tests/board/nav_track.hpp"
#include "host_tests/support/alloc_counter.hpp"

namespace {

namespace ref = sinu::test::mavref;
using sinu::board::MavlinkOutput;
using sinu::board::MavlinkOutputConfig;
using Bytes = std::vector<std::uint8_t>;

/// A UDP socket bound to an ephemeral loopback port: the flight controller.
class UdpReceiver {
 public:
  UdpReceiver() {
    fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = 0;
    EXPECT_EQ(::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
    socklen_t n = sizeof a;
    EXPECT_EQ(::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &n), 0);
    port_ = ntohs(a.sin_port);
  }
  ~UdpReceiver() { ::close(fd_); }
  std::uint16_t port() const { return port_; }
  /// Every datagram waiting (waits up to `timeout_ms` for the first).
  std::vector<Bytes> drain(int timeout_ms = 0) {
    std::vector<Bytes> out;
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, timeout_ms) <= 0) return out;
    std::array<std::uint8_t, 2048> buf{};
    for (ssize_t n; (n = ::recv(fd_, buf.data(), buf.size(), MSG_DONTWAIT)) > 0;)
      out.emplace_back(buf.begin(), buf.begin() + n);
    return out;
  }
  /// Discards what is waiting without allocating.
  void discard() {
    std::array<std::uint8_t, 2048> buf{};
    while (::recv(fd_, buf.data(), buf.size(), MSG_DONTWAIT) > 0) {
    }
  }

 private:
  int fd_ = -1;
  std::uint16_t port_ = 0;
};

struct Received {
  std::vector<Bytes> datagrams;
  std::vector<ref::Frame> frames;
};

/// Runs `solutions` of the track through a MavlinkOutput to UDP on loopback.
Received run_udp(const sinu::test::Track& track, int solutions, const MavlinkOutputConfig& config,
                 sinu::board::MavlinkOutputCounters* counters = nullptr) {
  UdpReceiver fc;
  sinu::hal::UdpSocket socket;
  EXPECT_TRUE(socket.open("127.0.0.1", fc.port())) << socket.last_error();
  MavlinkOutput out(config, socket);
  Received r;
  for (int k = 0; k < solutions; ++k) {
    out.on_solution(track.at(k));
    for (Bytes& d : fc.drain()) r.datagrams.push_back(std::move(d));  // loopback delivers at once
  }
  for (Bytes& d : fc.drain(100)) r.datagrams.push_back(std::move(d));
  for (const Bytes& d : r.datagrams) {
    const ref::ParseResult p = ref::parse(d);
    EXPECT_EQ(p.frames.size(), 1u) << "one frame per datagram";
    EXPECT_EQ(p.bad_crc + p.unknown_id + p.noise_bytes + p.incomplete_bytes, 0u);
    for (const ref::Frame& f : p.frames) r.frames.push_back(f);
  }
  EXPECT_EQ(socket.counters().sent, r.datagrams.size());
  EXPECT_EQ(socket.counters().errors + socket.counters().dropped, 0u);
  if (counters != nullptr) *counters = out.counters();
  return r;
}

TEST(MavlinkOutput, UdpLoopbackRatesSequenceAndContent) {
  const sinu::test::Track track;  // 50 Hz solutions, aligned from 0.5 s, a position reset at 10 s
  MavlinkOutputConfig config;
  config.system_id = 1;
  config.component_id = 191;
  config.odometry_hz = 10.0;
  config.gps_input_hz = 5.0;
  sinu::board::MavlinkOutputCounters counters;
  const Received r = run_udp(track, 1000, config, &counters);  // 20 s

  std::map<std::uint32_t, std::vector<const ref::Frame*>> by_id;
  for (const ref::Frame& f : r.frames) by_id[f.msgid].push_back(&f);
  EXPECT_EQ(by_id[0].size(), 20u);    // HEARTBEAT 1 Hz: t = 0 .. 19 s
  EXPECT_EQ(by_id[331].size(), 195u);  // ODOMETRY 10 Hz from alignment: 0.5 .. 19.9 s
  EXPECT_EQ(by_id[232].size(), 100u);  // GPS_INPUT 5 Hz: 0 .. 19.8 s
  EXPECT_EQ(counters.heartbeats, 20u);
  EXPECT_EQ(counters.odometry, 195u);
  EXPECT_EQ(counters.gps_inputs, 100u);
  EXPECT_EQ(counters.write_failures, 0u);

  // Periods from the messages' own time stamps (HEARTBEAT has none: its
  // period follows from the sequence positions of the other two).
  for (const auto& [id, period_us] : std::map<std::uint32_t, double>{{331, 100'000}, {232, 200'000}}) {
    const auto& frames = by_id[id];
    for (std::size_t i = 1; i < frames.size(); ++i)
      EXPECT_NEAR(frames[i]->f("time_usec") - frames[i - 1]->f("time_usec"), period_us, 1.0) << id << " #" << i;
  }
  EXPECT_EQ(by_id[331].front()->f("time_usec"), 500'000);
  // HEARTBEAT every whole second: the frame after it (ODOMETRY, or GPS_INPUT
  // before alignment) carries the same solution time.
  for (std::size_t i = 0, beats = 0; i + 1 < r.frames.size(); ++i)
    if (r.frames[i].msgid == 0) {
      EXPECT_NEAR(r.frames[i + 1].f("time_usec") * 1e-6, static_cast<double>(beats), 1e-6) << "beat " << beats;
      ++beats;
    }

  // One sequence for the component: 0, 1, 2, ... wrapping at 256 (315 frames).
  ASSERT_EQ(r.frames.size(), 315u);
  for (std::size_t i = 0; i < r.frames.size(); ++i) {
    EXPECT_EQ(r.frames[i].seq, i % 256) << i;
    EXPECT_EQ(r.frames[i].sysid, 1u);
    EXPECT_EQ(r.frames[i].compid, 191u);
  }

  // Content: the local position follows the track from the first aligned
  // point; the reset at 10 s counts once.
  for (const ref::Frame* f : by_id[331]) {
    const double t = f->f("time_usec") * 1e-6;
    EXPECT_NEAR(f->f("x"), 5.0 * (t - 0.5), 0.01) << t;
    EXPECT_NEAR(f->f("y"), 2.0 * (t - 0.5), 0.01) << t;
    EXPECT_NEAR(f->f("z"), 0.0, 0.01) << t;
    EXPECT_EQ(f->f("reset_counter"), t < 10.0 - 1e-9 ? 0 : 1) << t;
  }
  EXPECT_EQ(by_id[232].front()->f("fix_type"), 1) << "not aligned at 0 s";
  EXPECT_EQ(by_id[232].back()->f("fix_type"), 3);
}

TEST(MavlinkOutput, SerialPtyCarriesTheSameFrames) {
  const sinu::test::Track track;
  const MavlinkOutputConfig config;
  constexpr int kSolutions = 250;  // 5 s
  const Received udp = run_udp(track, kSolutions, config);

  int master = -1, slave = -1;
  std::array<char, 128> name{};
  ASSERT_EQ(openpty(&master, &slave, name.data(), nullptr, nullptr), 0);
  ::close(slave);  // the back end opens the tty by name, as on the board
  ASSERT_EQ(::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK), 0);
  sinu::hal::TermiosSerialPort port;
  ASSERT_TRUE(port.open(name.data(), 115200)) << port.last_error();
  MavlinkOutput out(config, port);
  Bytes stream;
  auto drain = [&](int timeout_ms) {
    std::array<std::uint8_t, 4096> buf{};
    pollfd p{master, POLLIN, 0};
    while (::poll(&p, 1, timeout_ms) > 0) {
      const ssize_t n = ::read(master, buf.data(), buf.size());
      if (n <= 0) break;
      stream.insert(stream.end(), buf.begin(), buf.begin() + n);
    }
  };
  for (int k = 0; k < kSolutions; ++k) {
    out.on_solution(track.at(k));
    drain(0);
  }
  drain(100);
  ::close(master);

  Bytes expected;
  for (const Bytes& d : udp.datagrams) expected.insert(expected.end(), d.begin(), d.end());
  EXPECT_EQ(out.counters().write_failures, 0u);
  EXPECT_EQ(stream.size(), expected.size());
  EXPECT_TRUE(stream == expected) << "the serial stream is the datagrams back to back";
  const ref::ParseResult p = ref::parse(stream);
  EXPECT_EQ(p.frames.size(), udp.frames.size());
  EXPECT_EQ(p.bad_crc + p.unknown_id + p.noise_bytes + p.incomplete_bytes, 0u);
}

TEST(MavlinkOutput, NoHeapAllocationPerMessage) {
  const sinu::test::Track track;
  UdpReceiver fc;
  sinu::hal::UdpSocket socket;
  ASSERT_TRUE(socket.open("127.0.0.1", fc.port()));
  MavlinkOutput out(MavlinkOutputConfig{}, socket);
  std::vector<sinu::board::NavSolution> solutions;
  for (int k = 0; k < 500; ++k) solutions.push_back(track.at(k));
  out.on_solution(solutions.front());
  fc.discard();

  sinu::test::AllocationScope scope;
  for (std::size_t k = 1; k < solutions.size(); ++k) {
    out.on_solution(solutions[k]);
    fc.discard();
  }
  const std::uint64_t allocations = scope.count();
  EXPECT_EQ(allocations, 0u);
  EXPECT_GT(out.counters().odometry, 90u);

  // The encoders alone, and the serial path.
  sinu::board::OdometryReference reference;
  reference.observe(solutions.back());
  sinu::board::mavlink::MavlinkFrame frame;
  int master = -1, slave = -1;
  ASSERT_EQ(openpty(&master, &slave, nullptr, nullptr, nullptr), 0);
  ASSERT_EQ(::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK), 0);
  sinu::hal::TermiosSerialPort port;
  ASSERT_TRUE(port.adopt(slave, 115200)) << port.last_error();
  MavlinkOutput serial_out(MavlinkOutputConfig{}, port);
  std::array<std::uint8_t, 4096> sink{};
  sinu::test::AllocationScope encoders;
  for (const auto& s : solutions) {
    sinu::board::encode_heartbeat(s, {}, frame);
    sinu::board::encode_odometry(s, reference, {}, frame);
    sinu::board::encode_gps_input(s, {}, frame);
    serial_out.on_solution(s);
    while (::read(master, sink.data(), sink.size()) > 0) {
    }
  }
  EXPECT_EQ(encoders.count(), 0u);
  EXPECT_GT(serial_out.counters().odometry, 90u);
  ::close(master);
}

TEST(UdpSocket, FailuresAreCountedNotFatal) {
  UdpReceiver fc;
  sinu::hal::UdpSocket socket;
  ASSERT_TRUE(socket.open("127.0.0.1", fc.port()));
  const Bytes too_big(70'000, 0x55);  // over the 65507-byte UDP payload limit
  EXPECT_EQ(socket.send(too_big), sinu::hal::DatagramStatus::Error);
  EXPECT_EQ(socket.counters().errors, 1u);
  EXPECT_EQ(socket.counters().last_errno, EMSGSIZE);
  const Bytes small{1, 2, 3};
  EXPECT_EQ(socket.send(small), sinu::hal::DatagramStatus::Ok) << "the socket still works";
  EXPECT_EQ(socket.counters().sent, 1u);
  const auto got = fc.drain(100);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0], small);
  sinu::hal::UdpSocket closed;
  EXPECT_EQ(closed.send(small), sinu::hal::DatagramStatus::Error) << "never opened";
}

}  // namespace
