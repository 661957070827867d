#include "hal/linux/i2c_dev.hpp"

#include <fcntl.h>
#include <linux/i2c-dev.h>
#include <linux/i2c.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>

namespace sinu::hal {

namespace {
// Longest register write we issue in one message (register address + payload).
constexpr std::size_t kMaxWrite = 32;
}  // namespace

LinuxI2cBus::~LinuxI2cBus() {
  if (fd_ >= 0) ::close(fd_);
}

bool LinuxI2cBus::open(const std::string& device) {
  fd_ = ::open(device.c_str(), O_RDWR | O_CLOEXEC);
  if (fd_ < 0) {
    last_error_ = device + ": " + std::strerror(errno);
    return false;
  }
  unsigned long funcs = 0;
  if (::ioctl(fd_, I2C_FUNCS, &funcs) < 0 || !(funcs & I2C_FUNC_I2C)) {
    last_error_ = device + ": adapter does not support plain I2C transfers (I2C_RDWR)";
    ::close(fd_);
    fd_ = -1;
    return false;
  }
  return true;
}

I2cStatus LinuxI2cBus::from_errno(int err) {
  last_error_ = std::strerror(err);
  switch (err) {
    case ENXIO:  // most adapters report a missing ACK as ENXIO or EREMOTEIO
    case EREMOTEIO: return I2cStatus::Nack;
    case ETIMEDOUT: return I2cStatus::Timeout;
    case EAGAIN:  // arbitration lost
    case EPROTO: return I2cStatus::BusError;
    default: return I2cStatus::Io;
  }
}

I2cStatus LinuxI2cBus::read_registers(std::uint8_t address, std::uint8_t reg, std::span<std::uint8_t> data) {
  if (fd_ < 0) return I2cStatus::Io;
  std::uint8_t reg_byte = reg;
  std::array<i2c_msg, 2> msgs{};
  msgs[0] = i2c_msg{address, 0, 1, &reg_byte};
  msgs[1] = i2c_msg{address, I2C_M_RD, static_cast<__u16>(data.size()), data.data()};
  i2c_rdwr_ioctl_data xfer{msgs.data(), 2};
  if (::ioctl(fd_, I2C_RDWR, &xfer) < 0) return from_errno(errno);
  return I2cStatus::Ok;
}

I2cStatus LinuxI2cBus::write_registers(std::uint8_t address, std::uint8_t reg, std::span<const std::uint8_t> data) {
  if (fd_ < 0) return I2cStatus::Io;
  if (data.size() + 1 > kMaxWrite) return I2cStatus::Io;
  std::array<std::uint8_t, kMaxWrite> buffer{};
  buffer[0] = reg;
  std::memcpy(buffer.data() + 1, data.data(), data.size());
  i2c_msg msg{address, 0, static_cast<__u16>(data.size() + 1), buffer.data()};
  i2c_rdwr_ioctl_data xfer{&msg, 1};
  if (::ioctl(fd_, I2C_RDWR, &xfer) < 0) return from_errno(errno);
  return I2cStatus::Ok;
}

}  // namespace sinu::hal
