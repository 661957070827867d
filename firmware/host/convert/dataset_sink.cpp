#include "firmware/host/convert/dataset_sink.hpp"

#include <filesystem>

#include "firmware/host/dataset/dataset_paths.hpp"

namespace sinu::convert {

DatasetSink::DatasetSink() {
  // Lossless, so the dataset replays to the same bits as the recording it
  // came from: t to the nanosecond (the HAL's resolution; hal::ns_to_s reads
  // the same double), values in shortest round-trip form.
  imu_.set_format(dataset::imu_col::t, {dataset::ColumnFormat::Style::Fixed, 9});
  for (std::size_t c = dataset::imu_col::ax; c < dataset::imu_col::count; ++c) imu_.set_format(c, {dataset::ColumnFormat::Style::Shortest, 0});
}

bool DatasetSink::open(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const dataset::DatasetPaths paths{dir};
  if (!imu_.open(paths.imu())) {
    error_ = imu_.error().to_string();
    return false;
  }
  if (!gps_.open(paths.gps())) {
    error_ = gps_.error().to_string();
    return false;
  }
  return true;
}

void DatasetSink::on_imu(const drivers::ImuSample& s) {
  dataset::CsvRow row;
  row.clear(dataset::imu_col::count);
  row.set(dataset::imu_col::t, hal::ns_to_s(s.t_ns));
  for (std::size_t i = 0; i < 3; ++i) {
    row.set(dataset::imu_col::ax + i, s.specific_force_b_m_s2[i]);
    row.set(dataset::imu_col::gx + i, s.angular_rate_b_rad_s[i]);
    if (s.has_mag) row.set(dataset::imu_col::mx + i, s.mag_b_uT[i]);
  }
  row.set(dataset::imu_col::temp, s.temp_degC);
  if (!imu_.write(row) && error_.empty()) error_ = imu_.error().to_string();
  ++rows_;
}

void DatasetSink::on_sentence(hal::TimeNs arrival_ns, std::string_view sentence) {
  std::int64_t us = (arrival_ns + 500) / 1000;
  if (have_last_ && us <= last_us_) us = last_us_ + 1;
  last_us_ = us;
  have_last_ = true;
  if (!gps_.write(static_cast<double>(us) * 1e-6, sentence) && error_.empty()) error_ = gps_.error().to_string();
  ++sentences_;
}

bool DatasetSink::close() {
  const bool imu_ok = imu_.close();
  const bool gps_ok = gps_.close();
  if (!imu_ok && error_.empty()) error_ = imu_.error().to_string();
  if (!gps_ok && error_.empty()) error_ = gps_.error().to_string();
  return imu_ok && gps_ok && error_.empty();
}

}  // namespace sinu::convert
