#include "firmware/host/replay/recording_source.hpp"

#include "firmware/board/nav_unit.hpp"

namespace sinu::replay {

bool RecordingSource::open(const std::string& path, std::string& error) {
  path_ = path;
  session_ = std::make_unique<hal::ReplaySession>();
  if (!session_->load(path, error)) return false;
  held_ = std::make_unique<est::RingBuffer<Held, kHeldSamples>>();
  fixes_ = std::make_unique<est::RingBuffer<drivers::GpsFix, kHeldFixes>>();
  return true;
}

void RecordingSource::full_scale(double& accel_m_s2, double& gyro_rad_s) const {
  board::full_scales(imu_config_, accel_m_s2, gyro_rad_s);
}

void RecordingSource::release_oldest() {
  const est::ImuSample& s = held_->front().sample;
  while (!fixes_->empty() && fixes_->front().arrival_s <= s.t_s) {
    feed_->on_fix(fixes_->front());
    fixes_->pop();
  }
  feed_->on_imu(s);
  last_fed_t_s_ = s.t_s;
  held_->pop();
}

void RecordingSource::on_imu(const drivers::ImuSample& d) {
  if (held_->full()) release_oldest();  // only above 1000 Hz
  Held h;
  h.t_ns = d.t_ns;
  h.sample = board::to_estimator(d);
  held_->push(h);
}

void RecordingSource::on_fix(const drivers::GpsFix& fix) {
  if (fix.arrival_s <= last_fed_t_s_) ++reordered_fixes_;  // a sample after its arrival was already fed
  if (fixes_->full()) {
    feed_->on_fix(fixes_->front());
    fixes_->pop();
    ++reordered_fixes_;
  }
  fixes_->push(fix);
}

void RecordingSource::on_tick(hal::TimeNs now_ns) {
  while (!held_->empty() && held_->front().t_ns <= now_ns - kReorderWindowNs) release_oldest();
}

bool RecordingSource::run(ReplayFeed& feed, std::string&) {
  feed_ = &feed;
  board::BoardLoop loop({session_->drdy(), session_->i2c(), session_->serial(), session_->clock()}, imu_config_);
  loop.run(*this);
  while (!held_->empty()) release_oldest();
  // Fixes that arrived after the last sample are not fed (as from a dataset).
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
  if (reordered_fixes_ > 0)
    add(std::to_string(reordered_fixes_) + " GPS fixes completed more than " +
        std::to_string(kReorderWindowNs / 1'000'000'000) + " s after they arrived, fed late");
  return n;
}

}  // namespace sinu::replay
