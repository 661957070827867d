#pragma once
// Datagram socket interface: one call sends one whole datagram, or nothing.
// Sending never blocks and never stops the caller: a datagram the link cannot
// take now is dropped and counted (telemetry is sent again at its next period;
// a late datagram is worth less than the next one).
#include <cstdint>
#include <span>

namespace sinu::hal {

enum class DatagramStatus : std::uint8_t {
  Ok = 0,       // the whole datagram was handed to the network stack
  Dropped = 1,  // not sent: the socket buffer is full (would block), try the next one
  Error = 2,    // not sent: an error (see the back end's counters)
};

class DatagramSocket {
 public:
  virtual ~DatagramSocket() = default;
  /// Sends `datagram` to the socket's destination without blocking.
  virtual DatagramStatus send(std::span<const std::uint8_t> datagram) = 0;
};

}  // namespace sinu::hal
