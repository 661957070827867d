#include "firmware/board/linux_board.hpp"

#include <array>
#include <cmath>

#include "drivers/gps/gps_setup.hpp"

namespace sinu::board {

bool LinuxBoard::setup_gps(const FlyConfig::Gps& o, std::string& error) {
  if (o.setup == "none") return true;
  namespace gs = drivers::gps_setup;
  const auto period_ms = static_cast<std::uint16_t>(std::lround(1000.0 / o.rate_hz));
  std::array<std::uint8_t, 64> a{}, b{};
  std::size_t na = 0, nb = 0;
  if (o.setup == "ubx") {
    na = gs::ubx_cfg_rate(period_ms, a);
    nb = gs::ubx_cfg_prt_uart1(o.setup_baud, b);
  } else if (o.setup == "ubx-valset") {
    na = gs::ubx_valset_rate_baud(period_ms, o.setup_baud, gs::kRam, a);
  } else {
    na = gs::pmtk220_fix_interval(period_ms, a);
    nb = gs::pmtk251_baud(o.setup_baud, b);
  }
  hal::SerialPort& port = devices().gps;  // recorded too, when recording
  // Rate first (understood at the old baud), then the baud change, then follow it.
  if (port.write({a.data(), na}).status != hal::SerialStatus::Ok ||
      (nb > 0 && port.write({b.data(), nb}).status != hal::SerialStatus::Ok)) {
    error = o.device + ": GPS set-up write failed: " + serial_.last_error();
    return false;
  }
  clock_.sleep_until_ns(clock_.now_ns() + 100'000'000);  // let the receiver apply it
  if (o.setup_baud != o.baud && !port.set_baud(o.setup_baud)) {
    error = o.device + ": " + serial_.last_error();
    return false;
  }
  return true;
}

bool LinuxBoard::open(const FlyConfig::Imu& imu, const FlyConfig::Gps& o, const std::string& record_path,
                      std::string& error) {
  if (!i2c_.open(imu.i2c)) return (error = i2c_.last_error()), false;
  if (!serial_.open(o.device, o.baud)) return (error = serial_.last_error()), false;
  if (!drdy_.open(imu.drdy_chip, imu.drdy_line)) return (error = drdy_.last_error()), false;
  drdy_.also_wake_on(serial_.fd());
  if (!record_path.empty() && !recording_.start(record_path, {drdy_, i2c_, serial_, clock_}, error)) return false;
  return setup_gps(o, error);
}

board::BoardDevices LinuxBoard::devices() { return recording_.devices({drdy_, i2c_, serial_, clock_}); }

}  // namespace sinu::board
