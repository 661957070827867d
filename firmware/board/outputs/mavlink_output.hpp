#pragma once
// The navigation solution out as MAVLink 2 to a flight controller: HEARTBEAT,
// ODOMETRY and GPS_INPUT (mavlink_messages.hpp), each at its own rate on the
// solutions' time line, over a serial port (a byte stream of frames) or a
// datagram socket (one frame per datagram). One sequence number counts every
// frame of this component. No allocation per message.
//
// Link budget: a frame is 12 bytes + payload: HEARTBEAT 21, ODOMETRY 245,
// GPS_INPUT up to 77. At the default rates that is ~2.9 kB/s: a UART needs
// 57600 baud (5.7 kB/s) at least, 115200 to leave room for the flight
// controller's own traffic.
#include <cstdint>

#include "firmware/board/nav_solution.hpp"
#include "firmware/board/outputs/mavlink_frame.hpp"
#include "firmware/board/outputs/odometry_reference.hpp"
#include "firmware/board/outputs/rate_schedule.hpp"
#include "hal/datagram_socket.hpp"
#include "hal/serial_port.hpp"

namespace sinu::board {

struct MavlinkOutputConfig {
  std::uint8_t system_id = 1;        // the vehicle's: a companion shares its flight controller's system id
  std::uint8_t component_id = 191;   // MAV_COMP_ID_ONBOARD_COMPUTER
  double heartbeat_hz = 1.0;         // the heartbeat microservice's nominal rate
  double odometry_hz = 10.0;         // <= 0: not sent
  double gps_input_hz = 5.0;         // <= 0: not sent
};

struct MavlinkOutputCounters {
  std::uint64_t heartbeats = 0, odometry = 0, gps_inputs = 0;  // frames written
  std::uint64_t bytes = 0;                                     // of the frames written
  std::uint64_t write_failures = 0;                            // frames the transport did not take
};

class MavlinkOutput {
 public:
  MavlinkOutput(const MavlinkOutputConfig& config, hal::SerialPort& port);
  MavlinkOutput(const MavlinkOutputConfig& config, hal::DatagramSocket& socket);

  /// Feeds one solution (in time order, at any rate): sends what is due at
  /// sol.t_s, in the order HEARTBEAT, ODOMETRY, GPS_INPUT. ODOMETRY waits for
  /// the first aligned solution.
  void on_solution(const NavSolution& sol);

  const MavlinkOutputCounters& counters() const { return counters_; }
  const OdometryReference& reference() const { return reference_; }

 private:
  MavlinkOutput(const MavlinkOutputConfig& config, hal::SerialPort* port, hal::DatagramSocket* socket);
  mavlink::FrameHeader next_header();
  bool write(const mavlink::MavlinkFrame& frame);

  MavlinkOutputConfig config_;
  hal::SerialPort* port_;
  hal::DatagramSocket* socket_;
  RateSchedule heartbeat_, odometry_, gps_input_;
  OdometryReference reference_;
  std::uint8_t sequence_ = 0;
  mavlink::MavlinkFrame frame_;
  MavlinkOutputCounters counters_;
};

}  // namespace sinu::board
