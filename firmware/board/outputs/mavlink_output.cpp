#include "firmware/board/outputs/mavlink_output.hpp"

#include "firmware/board/outputs/mavlink_messages.hpp"

namespace sinu::board {

MavlinkOutput::MavlinkOutput(const MavlinkOutputConfig& config, hal::SerialPort& port)
    : MavlinkOutput(config, &port, nullptr) {}

MavlinkOutput::MavlinkOutput(const MavlinkOutputConfig& config, hal::DatagramSocket& socket)
    : MavlinkOutput(config, nullptr, &socket) {}

MavlinkOutput::MavlinkOutput(const MavlinkOutputConfig& config, hal::SerialPort* port, hal::DatagramSocket* socket)
    : config_(config),
      port_(port),
      socket_(socket),
      heartbeat_(config.heartbeat_hz),
      odometry_(config.odometry_hz),
      gps_input_(config.gps_input_hz) {}

void MavlinkOutput::on_solution(const NavSolution& sol) {
  reference_.observe(sol);
  if (heartbeat_.due(sol.t_s) && encode_heartbeat(sol, next_header(), frame_) > 0 && write(frame_))
    ++counters_.heartbeats;
  // Not aligned: the slot passes unused (no origin, nothing to say).
  if (odometry_.due(sol.t_s) && sol.aligned && encode_odometry(sol, reference_, next_header(), frame_) > 0 &&
      write(frame_))
    ++counters_.odometry;
  if (gps_input_.due(sol.t_s) && encode_gps_input(sol, next_header(), frame_) > 0 && write(frame_))
    ++counters_.gps_inputs;
}

mavlink::FrameHeader MavlinkOutput::next_header() {
  return {sequence_++, config_.system_id, config_.component_id};  // wraps at 256 as the field does
}

bool MavlinkOutput::write(const mavlink::MavlinkFrame& frame) {
  bool ok = false;
  if (socket_ != nullptr) ok = socket_->send(frame.bytes()) == hal::DatagramStatus::Ok;
  if (port_ != nullptr) {
    const hal::SerialResult r = port_->write(frame.bytes());
    ok = r.status == hal::SerialStatus::Ok && r.bytes == frame.size;
  }
  if (ok) {
    counters_.bytes += frame.size;
  } else {
    ++counters_.write_failures;
  }
  return ok;
}

}  // namespace sinu::board
