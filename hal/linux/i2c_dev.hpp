#pragma once
// Linux back end of hal::I2cBus: /dev/i2c-N through the I2C_RDWR ioctl, so a
// register read is one transaction with a repeated start (no STOP between the
// register address and the data, which the ICM-20948 requires for burst reads).
#include <string>

#include "hal/i2c_bus.hpp"

namespace sinu::hal {

class LinuxI2cBus final : public I2cBus {
 public:
  LinuxI2cBus() = default;
  ~LinuxI2cBus() override;
  LinuxI2cBus(const LinuxI2cBus&) = delete;
  LinuxI2cBus& operator=(const LinuxI2cBus&) = delete;
  /// Opens e.g. "/dev/i2c-1". On false, last_error() says why.
  bool open(const std::string& device);
  I2cStatus read_registers(std::uint8_t address, std::uint8_t reg, std::span<std::uint8_t> data) override;
  I2cStatus write_registers(std::uint8_t address, std::uint8_t reg, std::span<const std::uint8_t> data) override;
  const std::string& last_error() const { return last_error_; }

 private:
  I2cStatus from_errno(int err);

  int fd_ = -1;
  std::string last_error_;
};

}  // namespace sinu::hal
