#include "firmware/board/output_devices.hpp"

#include "firmware/board/config/fly_setup.hpp"

namespace sinu::board {

bool OutputDevices::open(const FlyConfig::Outputs& o, std::string& error) {
  if (o.mavlink.enabled) {
    const MavlinkOutputConfig cfg = mavlink_output_config(o.mavlink);
    if (o.mavlink.transport == "udp") {
      if (!udp_.open(o.mavlink.udp_host, static_cast<std::uint16_t>(o.mavlink.udp_port))) {
        error = "outputs.mavlink: UDP " + o.mavlink.udp_host + ":" + std::to_string(o.mavlink.udp_port) + ": " +
                udp_.last_error();
        return false;
      }
      mavlink_ = std::make_unique<MavlinkOutput>(cfg, udp_);
      mavlink_target_ = "udp " + o.mavlink.udp_host + ":" + std::to_string(o.mavlink.udp_port);
    } else {
      if (!mavlink_serial_.open(o.mavlink.serial_device, o.mavlink.serial_baud)) {
        error = "outputs.mavlink: " + mavlink_serial_.last_error();
        return false;
      }
      mavlink_ = std::make_unique<MavlinkOutput>(cfg, mavlink_serial_);
      mavlink_target_ = o.mavlink.serial_device;
    }
  }
  if (o.nmea.enabled) {
    if (!nmea_serial_.open(o.nmea.device, o.nmea.baud)) {
      error = "outputs.nmea: " + nmea_serial_.last_error();
      return false;
    }
    nmea_ = std::make_unique<NmeaOutput>(nmea_serial_, nmea_output_config(o.nmea));
    nmea_device_ = o.nmea.device;
  }
  if (o.log.enabled) log_path_ = o.log.path;
  return true;
}

FlyOutputs OutputDevices::outputs() const {
  FlyOutputs out;
  out.mavlink = mavlink_.get();
  out.nmea = nmea_.get();
  out.log_path = log_path_;
  return out;
}

std::string OutputDevices::summary() const {
  std::string s;
  if (mavlink_) {
    const MavlinkOutputCounters& c = mavlink_->counters();
    s += "mavlink (" + mavlink_target_ + "): " + std::to_string(c.heartbeats) + " HEARTBEAT, " +
         std::to_string(c.odometry) + " ODOMETRY, " + std::to_string(c.gps_inputs) + " GPS_INPUT, " +
         std::to_string(c.write_failures) + " not sent";
  }
  if (nmea_) {
    const NmeaOutputCounters& c = nmea_->counters();
    s += std::string(s.empty() ? "" : "; ") + "nmea (" + nmea_device_ + "): " + std::to_string(c.epochs) + " epochs, " +
         std::to_string(c.write_errors) + " write errors";
  }
  if (!log_path_.empty()) s += std::string(s.empty() ? "" : "; ") + "log " + log_path_;
  return s.empty() ? "no outputs configured" : s;
}

}  // namespace sinu::board
