#include "firmware/host/convert/dataset_devices.hpp"

#include <cmath>
#include <cstring>

namespace sinu::convert {

hal::TimeNs seconds_to_ns(double t_s) { return std::llround(t_s * 1e9); }

DatasetDevices::DatasetDevices(drivers::EmulatedIcm20948& chip, hal::ManualClock& clock)
    : chip_(chip), clock_(clock) {}

bool DatasetDevices::open(const std::string& dir) {
  const dataset::DatasetPaths paths{dir};
  if (!imu_.open(paths.imu())) {
    error_ = imu_.error();
    return false;
  }
  has_gps_ = paths.has_gps();
  if (has_gps_) {
    if (!gps_.open(paths.gps())) {
      error_ = gps_.error();
      return false;
    }
    gps_done_ = false;
    next_line();
  }
  return true;
}

bool DatasetDevices::next_line() {
  dataset::NmeaLogLine l;
  const dataset::ReadStatus s = gps_.next(l);
  if (s != dataset::ReadStatus::Row) {
    if (s == dataset::ReadStatus::Error) error_ = gps_.error();
    gps_done_ = true;
    return false;
  }
  line_.assign(l.sentence);
  line_ += "\r\n";
  line_ns_ = seconds_to_ns(l.arrival_s);
  line_offset_ = 0;
  return true;
}

bool DatasetDevices::read_sample() {
  // The sensor always converts accel and gyro together: rows with part of
  // the IMU are merged into whole samples first (dataset/imu_row_merger.hpp).
  dataset::ImuRow row;
  while (!merger_.next(next_sample_)) {
    if (file_done_) {
      imu_done_ = true;
      return false;
    }
    const dataset::ReadStatus s = imu_.next(row.row);
    if (s == dataset::ReadStatus::Row) {
      merger_.add(row);
      continue;
    }
    if (s == dataset::ReadStatus::Error) error_ = imu_.error();
    file_done_ = true;
    merger_.finish();
  }
  have_sample_ = true;
  return true;
}

hal::TimeNs DatasetDevices::first_time_ns() {
  if (!have_sample_ && !imu_done_) read_sample();
  return have_sample_ ? seconds_to_ns(next_sample_.t_s) : 0;
}

hal::EdgeStatus DatasetDevices::wait_rising(hal::TimeNs timeout_ns, hal::TimeNs& edge_time_ns) {
  if (imu_done_) return hal::EdgeStatus::Closed;
  if (!have_sample_ && !read_sample()) return hal::EdgeStatus::Closed;
  // GPS bytes due before this edge wake the loop first (it reads them at
  // their time, as the board does); nothing due within the timeout (a gap in
  // imu.csv) is a timeout, as on the board.
  const hal::TimeNs t = seconds_to_ns(next_sample_.t_s);
  const hal::TimeNs give_up = clock_.now_ns() + timeout_ns;
  if (!gps_done_ && line_ns_ < t && line_ns_ <= give_up) {
    clock_.advance_to_ns(line_ns_);
    return hal::EdgeStatus::OtherInput;
  }
  if (t > give_up) {
    clock_.advance_to_ns(give_up);
    edge_time_ns = give_up;
    return hal::EdgeStatus::Timeout;
  }
  have_sample_ = false;
  ++samples_;
  drivers::EmulatedSample sample;
  const auto array = [](const Eigen::Vector3d& v) { return std::array<double, 3>{v.x(), v.y(), v.z()}; };
  sample.specific_force_b_m_s2 = array(next_sample_.specific_force_b_m_s2);
  sample.angular_rate_b_rad_s = array(next_sample_.angular_rate_b_rad_s);
  if (next_sample_.has_mag) sample.mag_b_uT = array(next_sample_.mag_b_uT);
  sample.temp_degC = next_sample_.has_temp ? next_sample_.temp_degC : drivers::EmulatedSample{}.temp_degC;
  clock_.advance_to_ns(t);
  chip_.load(sample);
  edge_time_ns = t;
  return hal::EdgeStatus::Edge;
}

hal::SerialResult DatasetDevices::read(std::span<std::uint8_t> out, hal::TimeNs timeout_ns) {
  if (gps_done_) return {imu_done_ ? hal::SerialStatus::Closed : hal::SerialStatus::Ok, 0, clock_.now_ns()};
  // Lines after the last IMU row are all delivered at the end.
  if (!imu_done_ && line_ns_ > clock_.now_ns() + timeout_ns) return {hal::SerialStatus::Ok, 0, clock_.now_ns()};
  const std::size_t n = std::min(out.size(), line_.size() - line_offset_);
  std::memcpy(out.data(), line_.data() + line_offset_, n);
  const hal::TimeNs t = line_ns_;
  clock_.advance_to_ns(t);
  line_offset_ += n;
  if (line_offset_ == line_.size()) next_line();
  return {hal::SerialStatus::Ok, n, t};
}

}  // namespace sinu::convert
