#include "firmware/cli/board_session.hpp"

namespace sinu::cli {

bool BoardSession::open(const board::FlyConfig& cfg, const drivers::Icm20948Config& imu, const std::string& record,
                        const EmulateRequest& e, std::string& error, bool& usage_error) {
  usage_error = false;
  emulating_ = !e.dataset.empty();
  if (!emulating_) return linux_.open(cfg.imu, cfg.gps, record, error);
  emulate::EmulateOptions eo;
  eo.dataset = e.dataset;
  eo.speed = e.speed;
  if (!emulate::parse_faults(e.faults, eo.faults, error)) {
    usage_error = true;
    return false;
  }
  return emulated_.open(eo, imu, record, error);
}

board::BoardDevices BoardSession::devices() {
  if (emulating_) return emulated_.devices();
  return linux_.devices();
}

hal::Clock& BoardSession::wall_clock() {
  if (emulating_) return emulated_.wall_clock();
  return linux_.clock();
}

const hal::TimeNs* BoardSession::edge_wall_ns() const {
  if (emulating_) return emulated_.edge_wall_ns();
  return nullptr;
}

hal::rec::RecordingWriter* BoardSession::writer() {
  if (emulating_) return emulated_.writer();
  return linux_.writer();
}

std::string BoardSession::error() const {
  if (emulating_) return emulated_.error();
  return {};
}

}  // namespace sinu::cli
