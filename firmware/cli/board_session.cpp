#include "firmware/cli/board_session.hpp"

namespace sinu::cli {

bool BoardSession::open(const board::FlyConfig& cfg, const drivers::Icm20948Config& imu, const std::string& record,
                        const EmulateRequest& e, std::string& error, bool& usage_error) {
  usage_error = false;
  emulating_ = !e.dataset.empty();
  if (!emulating_) return linux_.open(cfg.imu, cfg.gps, record, error);
#if SINU_HOST_MODES
  emulate::EmulateOptions eo;
  eo.dataset = e.dataset;
  eo.speed = e.speed;
  if (!emulate::parse_faults(e.faults, eo.faults, error)) {
    usage_error = true;
    return false;
  }
  return emulated_.open(eo, imu, record, error);
#else
  (void)imu;
  error = "--emulate is a host mode, not in this board-only build";
  usage_error = true;
  return false;
#endif
}

board::BoardDevices BoardSession::devices() {
#if SINU_HOST_MODES
  if (emulating_) return emulated_.devices();
#endif
  return linux_.devices();
}

hal::Clock& BoardSession::wall_clock() {
#if SINU_HOST_MODES
  if (emulating_) return emulated_.wall_clock();
#endif
  return linux_.clock();
}

const hal::TimeNs* BoardSession::edge_wall_ns() const {
#if SINU_HOST_MODES
  if (emulating_) return emulated_.edge_wall_ns();
#endif
  return nullptr;
}

hal::rec::RecordingWriter* BoardSession::writer() {
#if SINU_HOST_MODES
  if (emulating_) return emulated_.writer();
#endif
  return linux_.writer();
}

std::string BoardSession::error() const {
#if SINU_HOST_MODES
  if (emulating_) return emulated_.error();
#endif
  return {};
}

}  // namespace sinu::cli
