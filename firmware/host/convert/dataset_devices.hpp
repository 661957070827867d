#pragma once
// A dataset folder as board devices, for `sinu convert DATASET RAW`: each
// imu.csv row becomes a data-ready edge at its time with the row loaded into
// the emulated ICM-20948's registers; each gps.nmea line becomes a serial
// chunk ("sentence\r\n") arriving at its time. Run the BoardLoop over these
// with recording taps and the raw recording is what the board would have
// recorded, had it seen exactly this data.
#include <cstdint>
#include <string>

#include "drivers/imu/emulated_icm20948.hpp"
#include "firmware/host/dataset/csv_table.hpp"
#include "firmware/host/dataset/dataset_paths.hpp"
#include "firmware/host/dataset/diagnostic.hpp"
#include "firmware/host/dataset/imu_csv.hpp"
#include "firmware/host/dataset/imu_row_merger.hpp"
#include "firmware/host/dataset/nmea_log.hpp"
#include "hal/gpio_edge.hpp"
#include "hal/replay/manual_clock.hpp"
#include "hal/serial_port.hpp"

namespace sinu::convert {

/// Seconds (as written in a dataset, to the microsecond) <-> HAL nanoseconds.
hal::TimeNs seconds_to_ns(double t_s);

class DatasetDevices final : public hal::GpioEdge, public hal::SerialPort {
 public:
  DatasetDevices(drivers::EmulatedIcm20948& chip, hal::ManualClock& clock);
  /// Opens imu.csv (and gps.nmea if present). On false, error() says why.
  bool open(const std::string& dataset_dir);
  hal::EdgeStatus wait_rising(hal::TimeNs timeout_ns, hal::TimeNs& edge_time_ns) override;
  bool set_baud(std::uint32_t) override { return true; }
  hal::SerialResult read(std::span<std::uint8_t> out, hal::TimeNs timeout_ns) override;
  hal::SerialResult write(std::span<const std::uint8_t> bytes) override { return {hal::SerialStatus::Ok, bytes.size(), 0}; }
  /// A read error in either file (empty if none).
  const dataset::Diagnostic& error() const { return error_; }
  /// Whole IMU samples loaded into the chip (rows with part of the IMU merged).
  std::uint64_t samples() const { return samples_; }
  /// Rows without a gyro reading, folded into the next sample.
  std::uint64_t folded_rows() const { return merger_.counts().rows_folded; }
  /// Rows left out: a gyro reading before any accelerometer one (merger's counts).
  std::uint64_t skipped_rows() const { return merger_.counts().left_out; }
  /// Time of the first imu.csv row (0 if none).
  hal::TimeNs first_time_ns();

 private:
  bool next_line();
  bool read_sample();

  drivers::EmulatedIcm20948& chip_;
  hal::ManualClock& clock_;
  dataset::CsvReader imu_{dataset::kImuSchema};
  dataset::NmeaLogReader gps_;
  dataset::ImuRowMerger merger_;
  est::ImuSample next_sample_;  // read ahead, delivered when no GPS bytes are due before it
  bool have_sample_ = false;
  bool has_gps_ = false, imu_done_ = false, gps_done_ = true;
  bool file_done_ = false;  // imu.csv read to its end (samples may still wait in merger_)
  std::string line_;        // the pending gps.nmea sentence + CR LF
  hal::TimeNs line_ns_ = 0;
  std::size_t line_offset_ = 0;
  std::uint64_t samples_ = 0;
  dataset::Diagnostic error_;
};

}  // namespace sinu::convert
