#include "hal/recording/recording_format.hpp"

namespace sinu::hal::rec {

const char* to_string(Kind k) {
  switch (k) {
    case Kind::I2cRead: return "i2c_read";
    case Kind::I2cWrite: return "i2c_write";
    case Kind::SerialRx: return "serial_rx";
    case Kind::SerialTx: return "serial_tx";
    case Kind::GpioEdge: return "gpio_edge";
    case Kind::SerialBaud: return "serial_baud";
    case Kind::EdgeTimeout: return "edge_timeout";
  }
  return "unknown";
}

bool is_known(std::uint8_t kind) {
  return kind >= static_cast<std::uint8_t>(Kind::I2cRead) && kind <= static_cast<std::uint8_t>(Kind::EdgeTimeout);
}

std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc) {
  constexpr std::uint32_t kPolynomial = 0xEDB88320u;  // reflected IEEE 802.3
  crc = ~crc;
  for (std::uint8_t b : bytes) {
    crc ^= b;
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (kPolynomial & (0u - (crc & 1u)));
  }
  return ~crc;
}

}  // namespace sinu::hal::rec
