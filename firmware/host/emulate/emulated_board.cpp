#include "firmware/host/emulate/emulated_board.hpp"

#include <fcntl.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace sinu::emulate {

namespace {

constexpr hal::TimeNs kStartUpNs = 1'000'000'000;  // the driver starts in the second before the first sample

bool to_number(const std::string& s, double& v) {
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size() && std::isfinite(v);
}

/// Readable bytes waiting on a tty (the pty's slave side).
int queued(int fd) {
  int n = 0;
  return ::ioctl(fd, FIONREAD, &n) == 0 ? n : -1;
}

}  // namespace

bool parse_faults(const std::string& text, std::vector<EmulatedFault>& out, std::string& error) {
  out.clear();
  std::istringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    const std::size_t a = item.find(':'), b = item.find(':', a == std::string::npos ? a : a + 1);
    EmulatedFault f;
    const std::string kind = item.substr(0, a);
    bool ok = a != std::string::npos && b != std::string::npos && to_number(item.substr(a + 1, b - a - 1), f.start_s) &&
              to_number(item.substr(b + 1), f.duration_s) && f.duration_s > 0.0;
    if (kind == "i2c-stop") f.kind = FaultKind::I2cStop;
    else if (kind == "gps-garbage") f.kind = FaultKind::GpsGarbage;
    else if (kind == "drdy-lost") f.kind = FaultKind::DrdyLost;
    else ok = false;
    if (!ok) {
      error = "--fault: '" + item + "' is not KIND:START:DURATION with KIND i2c-stop, gps-garbage or drdy-lost, "
              "START in the dataset's t and DURATION > 0 [s]";
      return false;
    }
    out.push_back(f);
  }
  return true;
}

EmulatedBoard::EmulatedBoard() = default;

EmulatedBoard::~EmulatedBoard() {
  if (probe_fd_ >= 0) ::close(probe_fd_);
  if (master_fd_ >= 0) ::close(master_fd_);
}

bool EmulatedBoard::open(const EmulateOptions& o, const drivers::Icm20948Config& imu, const std::string& record_path,
                         std::string& error) {
  options_ = o;
  chip_ = std::make_unique<drivers::EmulatedIcm20948>(imu.address, imu.mounting);
  data_ = std::make_unique<convert::DatasetDevices>(*chip_, clock_);
  if (!data_->open(o.dataset)) {
    error = data_->error().to_string();
    return false;
  }
  master_fd_ = ::posix_openpt(O_RDWR | O_NOCTTY);
  std::array<char, 128> name{};
  if (master_fd_ < 0 || ::grantpt(master_fd_) != 0 || ::unlockpt(master_fd_) != 0 ||
      ::ptsname_r(master_fd_, name.data(), name.size()) != 0) {
    error = std::string("--emulate: cannot make a pseudo-terminal for the GPS: ") + std::strerror(errno);
    return false;
  }
  pty_path_ = name.data();
  if (!serial_.open(pty_path_, 115200)) {
    error = "--emulate: " + serial_.last_error();
    return false;
  }
  serial_.stamp_with(&clock_);  // bytes carry the dataset's time, as the board's clock
  probe_fd_ = ::open(pty_path_.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
  if (probe_fd_ < 0) {
    error = "--emulate: " + pty_path_ + ": " + std::strerror(errno);
    return false;
  }
  clock_.advance_to_ns(data_->first_time_ns() - kStartUpNs);
  t0_ns_ = clock_.now_ns();
  wall0_ns_ = wall_.now_ns();
  return record_path.empty() || recording_.start(record_path, {*this, *chip_, serial_, clock_}, error);
}

board::BoardDevices EmulatedBoard::devices() { return recording_.devices({*this, *chip_, serial_, clock_}); }

std::string EmulatedBoard::error() const {
  return data_ && !data_->error().message.empty() ? data_->error().to_string() : std::string();
}

bool EmulatedBoard::in_fault(FaultKind kind, hal::TimeNs t_ns) const {
  const double t = hal::ns_to_s(t_ns);
  for (const EmulatedFault& f : options_.faults) {
    if (f.kind == kind && t >= f.start_s && t < f.start_s + f.duration_s) return true;
  }
  return false;
}

void EmulatedBoard::pace(hal::TimeNs t_ns) {
  if (options_.speed <= 0.0) return;
  const auto target = wall0_ns_ + static_cast<hal::TimeNs>(static_cast<double>(t_ns - t0_ns_) / options_.speed);
  wall_.sleep_until_ns(target);
}

bool EmulatedBoard::send_gps_line() {
  std::array<std::uint8_t, 4096> buf{};
  const hal::SerialResult r = data_->read(buf, 0);
  if (r.bytes == 0) return false;
  ++counters_.gps_lines;
  if (in_fault(FaultKind::GpsGarbage, r.time_ns)) {  // line noise: what a loose connector sends
    ++counters_.garbage_lines;
    for (std::size_t i = 0; i < r.bytes; ++i) {
      garbage_state_ ^= garbage_state_ << 13;
      garbage_state_ ^= garbage_state_ >> 17;
      garbage_state_ ^= garbage_state_ << 5;
      buf[i] = static_cast<std::uint8_t>(garbage_state_);
    }
  }
  const int before = std::max(0, queued(probe_fd_));
  std::size_t done = 0;
  while (done < r.bytes) {
    const ssize_t n = ::write(master_fd_, buf.data() + done, r.bytes - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  // The pty hands bytes over asynchronously: wait (at most 1 s) until the
  // loop can read them all, so they are read, and stamped, at this time.
  const hal::TimeNs give_up = wall_.now_ns() + 1'000'000'000;
  while (queued(probe_fd_) >= 0 && queued(probe_fd_) < before + static_cast<int>(r.bytes) && wall_.now_ns() < give_up) {
    wall_.sleep_until_ns(wall_.now_ns() + 20'000);
  }
  return true;
}

hal::EdgeStatus EmulatedBoard::wait_rising(hal::TimeNs timeout_ns, hal::TimeNs& edge_time_ns) {
  const hal::EdgeStatus st = data_->wait_rising(timeout_ns, edge_time_ns);
  const hal::TimeNs now = clock_.now_ns();
  const bool dead = in_fault(FaultKind::I2cStop, now);
  if (dead != bus_dead_) {  // the bus stops answering, or comes back
    bus_dead_ = dead;
    if (dead) {
      ++counters_.i2c_stops;
      chip_->inject(drivers::EmulatorFault::BusDead);
    } else {
      chip_->clear_faults();
    }
  }
  switch (st) {
    case hal::EdgeStatus::Closed: return st;
    case hal::EdgeStatus::OtherInput:
      pace(now);
      send_gps_line();
      return st;
    case hal::EdgeStatus::Edge:
      pace(edge_time_ns);
      edge_wall_ns_ = wall_.now_ns();
      ++counters_.edges;
      // A lost edge: the loop's wait ends (times out) when it would have
      // risen, and its poll finds the sample.
      if (in_fault(FaultKind::DrdyLost, edge_time_ns)) {
        ++counters_.edges_lost;
        return hal::EdgeStatus::Timeout;
      }
      return st;
    default:
      pace(now);
      return st;
  }
}

}  // namespace sinu::emulate
