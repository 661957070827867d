#pragma once
// I2C master interface: register block transfers as sensors expect them.
// read_registers is one combined transaction: START addr+W reg, REPEATED
// START addr+R, n bytes, STOP (I2C_RDWR with two messages on Linux).
#include <cstdint>
#include <span>

namespace sinu::hal {

enum class I2cStatus : std::uint8_t {
  Ok = 0,
  Nack = 1,      // the device did not acknowledge (absent, busy, wrong address)
  Timeout = 2,   // the bus did not complete the transfer (stuck SDA/SCL, dead device)
  BusError = 3,  // arbitration lost or another controller-reported error
  Io = 4,        // the back end failed (no such bus, permission, replay mismatch)
};

const char* to_string(I2cStatus s);

class I2cBus {
 public:
  virtual ~I2cBus() = default;
  /// Reads data.size() consecutive registers starting at `reg` of the 7-bit device `address`.
  virtual I2cStatus read_registers(std::uint8_t address, std::uint8_t reg, std::span<std::uint8_t> data) = 0;
  /// Writes data.size() consecutive registers starting at `reg`.
  virtual I2cStatus write_registers(std::uint8_t address, std::uint8_t reg, std::span<const std::uint8_t> data) = 0;
};

}  // namespace sinu::hal
