#include "firmware/host/replay/dataset_source.hpp"

#include "firmware/host/dataset/imu_csv.hpp"

namespace sinu::replay {

bool DatasetSource::open(const std::string& dir, std::string& error) {
  paths_ = dataset::DatasetPaths{dir};
  if (!imu_.open(paths_.imu())) {
    error = imu_.error().to_string();
    return false;
  }
  has_gps_ = paths_.has_gps();
  if (has_gps_ && !gps_.open(paths_.gps())) {
    error = gps_.error().to_string();
    return false;
  }
  return true;
}

bool DatasetSource::run(ReplayFeed& feed, std::string& error) {
  drivers::GpsFix fix;
  dataset::ReadStatus gps_st = has_gps_ ? gps_.next(fix) : dataset::ReadStatus::End;
  const auto deliver = [&](const est::ImuSample& s) {
    while (gps_st == dataset::ReadStatus::Row && fix.arrival_s <= s.t_s) {
      feed.on_fix(fix);
      gps_st = gps_.next(fix);
    }
    feed.on_imu(s);
    imu_end_s_ = s.t_s;
  };
  dataset::CsvRow row;
  est::ImuSample sample;
  dataset::ReadStatus st;
  while ((st = imu_.next(row)) == dataset::ReadStatus::Row) {
    merger_.add(dataset::ImuRow{row});
    while (merger_.next(sample)) deliver(sample);
  }
  merger_.finish();
  while (merger_.next(sample)) deliver(sample);
  // Fixes after the last IMU sample are never used; many of them is a clock
  // (or unit) mismatch between the two files, which the summary names.
  if (st != dataset::ReadStatus::Error && gps_st == dataset::ReadStatus::Row) first_fix_after_imu_s_ = fix.arrival_s;
  for (; st != dataset::ReadStatus::Error && gps_st == dataset::ReadStatus::Row; gps_st = gps_.next(fix)) ++fixes_after_imu_;
  if (st == dataset::ReadStatus::Error) {
    error = imu_.error().to_string();
    return false;
  }
  if (gps_st == dataset::ReadStatus::Error) {
    error = gps_.error().to_string();
    return false;
  }
  return true;
}

SourceCounters DatasetSource::counters() const {
  SourceCounters c;
  c.incomplete_rows = merger_.counts().left_out;
  c.rows_folded = merger_.counts().rows_folded;
  c.accel_held = merger_.counts().accel_held;
  c.accel_interpolated = merger_.counts().accel_interpolated;
  c.corrupt_sentences = has_gps_ ? gps_.corrupt() : 0;
  c.time_anomalies = imu_.time_anomalies();
  c.non_finite_rows = imu_.non_finite_rows();
  if (!imu_.first_anomaly().message.empty()) c.first_anomaly = imu_.first_anomaly().to_string();
  c.fixes_after_imu = fixes_after_imu_;
  c.first_fix_after_imu_s = first_fix_after_imu_s_;
  c.imu_end_s = imu_end_s_;
  return c;
}

std::string DatasetSource::default_truth() const { return paths_.has_truth() ? paths_.truth() : std::string(); }

}  // namespace sinu::replay
