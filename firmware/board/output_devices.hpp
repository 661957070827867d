#pragma once
// The outputs sinu.toml turns on, opened on their Linux devices: MAVLink over
// UDP or a serial port, NMEA on a serial port, and the navigation log's path.
#include <memory>
#include <string>

#include "firmware/board/config/fly_config.hpp"
#include "firmware/board/fly_loop.hpp"
#include "hal/linux/termios_serial.hpp"
#include "hal/linux/udp_socket.hpp"

namespace sinu::board {

class OutputDevices {
 public:
  /// Opens what `outputs` enables; false with `error` naming the device otherwise.
  bool open(const FlyConfig::Outputs& outputs, std::string& error);
  FlyOutputs outputs() const;
  /// One line: what was sent where (for the end of a flight).
  std::string summary() const;

 private:
  hal::UdpSocket udp_;
  hal::TermiosSerialPort mavlink_serial_, nmea_serial_;
  std::unique_ptr<MavlinkOutput> mavlink_;
  std::unique_ptr<NmeaOutput> nmea_;
  std::string log_path_, mavlink_target_, nmea_device_;
};

}  // namespace sinu::board
