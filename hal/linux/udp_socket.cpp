#include "hal/linux/udp_socket.hpp"

#include <netdb.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace sinu::hal {

UdpSocket::~UdpSocket() {
  if (fd_ >= 0) ::close(fd_);
}

bool UdpSocket::open(const std::string& host, std::uint16_t port) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_DGRAM;
  hints.ai_protocol = IPPROTO_UDP;
  addrinfo* found = nullptr;
  const std::string service = std::to_string(port);
  if (const int rc = ::getaddrinfo(host.c_str(), service.c_str(), &hints, &found); rc != 0) {
    last_error_ = host + ": " + ::gai_strerror(rc);
    return false;
  }
  // The first address that gives a socket is the destination.
  for (const addrinfo* a = found; a != nullptr; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    fd_ = fd;
    std::memcpy(&destination_, a->ai_addr, a->ai_addrlen);
    destination_bytes_ = a->ai_addrlen;
    break;
  }
  const int socket_errno = errno;
  ::freeaddrinfo(found);
  if (fd_ < 0) {
    last_error_ = std::string("socket: ") + std::strerror(socket_errno);
    return false;
  }
  return true;
}

DatagramStatus UdpSocket::send(std::span<const std::uint8_t> datagram) {
  if (fd_ < 0) {
    ++counters_.errors;
    counters_.last_errno = EBADF;
    return DatagramStatus::Error;
  }
  // Unconnected sendto(): an ICMP "port unreachable" from a receiver that is
  // not up yet is not reported back as an error on the next send.
  const ssize_t n = ::sendto(fd_, datagram.data(), datagram.size(), MSG_DONTWAIT,
                             reinterpret_cast<const sockaddr*>(&destination_), destination_bytes_);
  if (n == static_cast<ssize_t>(datagram.size())) {
    ++counters_.sent;
    return DatagramStatus::Ok;
  }
  counters_.last_errno = n < 0 ? errno : EMSGSIZE;  // a short datagram is as good as none
  if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == ENOBUFS)) {
    ++counters_.dropped;
    return DatagramStatus::Dropped;
  }
  ++counters_.errors;
  return DatagramStatus::Error;
}

}  // namespace sinu::hal
