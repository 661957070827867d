#pragma once
// The board's devices for `sinu fly` and `sinu bench`: the companion
// computer's (Linux: I2C, GPIO, tty), or on the host an emulated board
// playing a dataset (host/emulate, --emulate): the same loop either way.
#include <memory>
#include <string>

#include "firmware/board/board_loop.hpp"
#include "firmware/board/config/fly_config.hpp"
#include "firmware/board/linux_board.hpp"
#include "firmware/host/emulate/emulated_board.hpp"

namespace sinu::cli {

struct EmulateRequest {
  std::string dataset;  // "": the real devices
  double speed = 1.0;
  std::string faults;
};

class BoardSession {
 public:
  /// Opens the devices of `config` (or the emulation); `record` non-empty:
  /// records the traffic. False with `error` (usage errors flagged) otherwise.
  bool open(const board::FlyConfig& config, const drivers::Icm20948Config& imu, const std::string& record,
            const EmulateRequest& emulate, std::string& error, bool& usage_error);
  board::BoardDevices devices();
  hal::Clock& wall_clock();
  /// Wall time of the latest edge when edges are not on the wall clock (emulation), else nullptr.
  const hal::TimeNs* edge_wall_ns() const;
  hal::rec::RecordingWriter* writer();
  /// A read error of the emulation's dataset ("" if none).
  std::string error() const;

 private:
  board::LinuxBoard linux_;
  emulate::EmulatedBoard emulated_;
  bool emulating_ = false;
};

}  // namespace sinu::cli
