#pragma once
// Linux back end of hal::DatagramSocket: a non-blocking POSIX UDP socket
// sending to one host:port (resolved once, at open). Failed sends are counted
// by kind and reported as a status, never thrown or logged: the send path does
// no allocation, so it can run once per telemetry message.
#include <sys/socket.h>

#include <cstdint>
#include <string>

#include "hal/datagram_socket.hpp"

namespace sinu::hal {

struct UdpCounters {
  std::uint64_t sent = 0;     // datagrams handed to the stack
  std::uint64_t dropped = 0;  // socket buffer full (EAGAIN, ENOBUFS)
  std::uint64_t errors = 0;   // any other failure (EMSGSIZE, ENETUNREACH, ...)
  int last_errno = 0;         // of the last dropped or failed send (0: none)
};

class UdpSocket final : public DatagramSocket {
 public:
  UdpSocket() = default;
  ~UdpSocket() override;
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;
  /// Opens a socket sending to `host` (numeric IPv4/IPv6 address or a name)
  /// and `port`. False with last_error() if the host does not resolve or the
  /// socket cannot be made.
  bool open(const std::string& host, std::uint16_t port);
  DatagramStatus send(std::span<const std::uint8_t> datagram) override;
  const UdpCounters& counters() const { return counters_; }
  const std::string& last_error() const { return last_error_; }  // of open()

 private:
  int fd_ = -1;
  sockaddr_storage destination_{};
  socklen_t destination_bytes_ = 0;
  UdpCounters counters_;
  std::string last_error_;
};

}  // namespace sinu::hal
