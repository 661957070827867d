#pragma once
// BoardSink that writes a dataset folder: imu.csv rows and gps.nmea lines
// (dataset-format.md). imu.csv is lossless (t in ns, values in shortest
// round-trip form). Sentences that arrived in one serial chunk share its
// time; gps.nmea needs strictly increasing times, so each later one is
// stamped 1 us after the previous (the file's resolution).
#include <string>

#include "firmware/board/board_loop.hpp"
#include "firmware/host/dataset/csv_table.hpp"
#include "firmware/host/dataset/imu_csv.hpp"
#include "firmware/host/dataset/nmea_log.hpp"

namespace sinu::convert {

class DatasetSink final : public board::BoardSink {
 public:
  DatasetSink();
  bool open(const std::string& dir);
  bool close();
  void on_imu(const drivers::ImuSample& s) override;
  void on_sentence(hal::TimeNs arrival_ns, std::string_view sentence) override;
  void on_fix(const drivers::GpsFix&) override { ++fixes_; }
  const std::string& error() const { return error_; }
  std::uint64_t rows() const { return rows_; }
  std::uint64_t sentences() const { return sentences_; }
  std::uint64_t fixes() const { return fixes_; }

 private:
  dataset::CsvWriter imu_{dataset::kImuSchema};
  dataset::NmeaLogWriter gps_;
  std::int64_t last_us_ = 0;
  bool have_last_ = false;
  std::uint64_t rows_ = 0, sentences_ = 0, fixes_ = 0;
  std::string error_;
};

}  // namespace sinu::convert
