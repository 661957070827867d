#include "hal/linux/termios_serial.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

namespace sinu::hal {

namespace {

bool baud_constant(std::uint32_t baud, speed_t& out) {
  switch (baud) {
    case 4800: out = B4800; return true;
    case 9600: out = B9600; return true;
    case 19200: out = B19200; return true;
    case 38400: out = B38400; return true;
    case 57600: out = B57600; return true;
    case 115200: out = B115200; return true;
    case 230400: out = B230400; return true;
    case 460800: out = B460800; return true;
    case 921600: out = B921600; return true;
    default: return false;
  }
}

}  // namespace

TermiosSerialPort::~TermiosSerialPort() {
  if (fd_ >= 0) ::close(fd_);
}

bool TermiosSerialPort::open(const std::string& device, std::uint32_t baud) {
  const int fd = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    last_error_ = device + ": " + std::strerror(errno);
    return false;
  }
  return adopt(fd, baud);
}

bool TermiosSerialPort::adopt(int fd, std::uint32_t baud) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = fd;
  const int flags = ::fcntl(fd_, F_GETFL);
  if (flags < 0 || ::fcntl(fd_, F_SETFL, flags | O_NONBLOCK) < 0) {
    last_error_ = std::string("fcntl: ") + std::strerror(errno);
    return false;
  }
  termios tio{};
  if (::tcgetattr(fd_, &tio) < 0) {
    last_error_ = std::string("tcgetattr: ") + std::strerror(errno);
    return false;
  }
  ::cfmakeraw(&tio);                   // no echo, no canonical mode, no translation, 8 bits
  tio.c_cflag &= ~static_cast<tcflag_t>(PARENB | CSTOPB | CRTSCTS);  // N, 1 stop bit, no RTS/CTS
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);      // no XON/XOFF
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  if (::tcsetattr(fd_, TCSANOW, &tio) < 0) {
    last_error_ = std::string("tcsetattr: ") + std::strerror(errno);
    return false;
  }
  return set_baud(baud);
}

bool TermiosSerialPort::set_baud(std::uint32_t baud) {
  speed_t speed{};
  if (!baud_constant(baud, speed)) {
    last_error_ = "unsupported baud rate " + std::to_string(baud);
    return false;
  }
  termios tio{};
  if (fd_ < 0 || ::tcgetattr(fd_, &tio) < 0 || ::cfsetispeed(&tio, speed) < 0 || ::cfsetospeed(&tio, speed) < 0 ||
      ::tcsetattr(fd_, TCSANOW, &tio) < 0) {
    last_error_ = std::string("set baud: ") + std::strerror(errno);
    return false;
  }
  return true;
}

SerialResult TermiosSerialPort::fail(const char* what) {
  last_error_ = std::string(what) + ": " + std::strerror(errno);
  return {SerialStatus::Error, 0};
}

SerialResult TermiosSerialPort::read(std::span<std::uint8_t> out, TimeNs timeout_ns) {
  if (fd_ < 0) return {SerialStatus::Closed, 0};
  pollfd p{fd_, POLLIN, 0};
  const int timeout_ms = static_cast<int>((timeout_ns + 999'999) / 1'000'000);
  const int r = ::poll(&p, 1, timeout_ms);
  if (r < 0) return errno == EINTR ? SerialResult{} : fail("poll");
  if (r == 0) return {};
  const ssize_t n = ::read(fd_, out.data(), out.size());
  if (n > 0) {
    if (stamp_clock_) return {SerialStatus::Ok, static_cast<std::size_t>(n), stamp_clock_->now_ns()};
    timespec now{};
    ::clock_gettime(CLOCK_MONOTONIC, &now);  // the clock of MonotonicClock
    return {SerialStatus::Ok, static_cast<std::size_t>(n), TimeNs{now.tv_sec} * 1'000'000'000 + now.tv_nsec};
  }
  if (n == 0) return {SerialStatus::Closed, 0};
  if (errno == EAGAIN || errno == EINTR) return {};
  if (errno == EIO) return {SerialStatus::Closed, 0};  // the other side of a pty hung up
  return fail("read");
}

SerialResult TermiosSerialPort::write(std::span<const std::uint8_t> bytes) {
  if (fd_ < 0) return {SerialStatus::Closed, 0};
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EAGAIN) {
      pollfd p{fd_, POLLOUT, 0};
      if (::poll(&p, 1, 1000) <= 0) return {SerialStatus::Error, done};
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    SerialResult r = fail("write");
    r.bytes = done;
    return r;
  }
  return {SerialStatus::Ok, done};
}

}  // namespace sinu::hal
