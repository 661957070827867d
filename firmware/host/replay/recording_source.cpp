#include "firmware/host/replay/recording_source.hpp"

#include "firmware/board/nav_unit.hpp"

namespace sinu::replay {

bool RecordingSource::open(const std::string& path, std::string& error) {
  path_ = path;
  session_ = std::make_unique<hal::ReplaySession>();
  return session_->load(path, error);
}

void RecordingSource::full_scale(double& accel_m_s2, double& gyro_rad_s) const {
  board::full_scales(imu_config_, accel_m_s2, gyro_rad_s);
}

void RecordingSource::on_imu(const drivers::ImuSample& d) { feed_->on_imu(board::to_estimator(d)); }

bool RecordingSource::run(ReplayFeed& feed, std::string&) {
  feed_ = &feed;
  board::BoardLoop loop({session_->drdy(), session_->i2c(), session_->serial(), session_->clock()}, imu_config_);
  loop.run(*this);
  counters_.corrupt_sentences = loop.gps_counters().sentences.corrupt();
  imu_errors_ = loop.imu().counters().i2c_errors;
  desyncs_ = session_->desyncs();
  return true;
}

std::string RecordingSource::note() const {
  std::string n = session_ ? session_->stop_message() : std::string();
  auto add = [&n](const std::string& s) { n += (n.empty() ? "" : "; ") + s; };
  if (desyncs_ > 0)
    add(std::to_string(desyncs_) + " records did not match the driver's requests (other --mounting or driver "
        "settings than when recorded?)");
  if (imu_errors_ > 0) add(std::to_string(imu_errors_) + " IMU transfers failed as recorded");
  return n;
}

}  // namespace sinu::replay
