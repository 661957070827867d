#pragma once
// Reads every file of a dataset folder completely and summarises it; stops
// at the first error with its file:line:column. Backs `sinu inspect dataset`.
#include <cstdint>
#include <optional>
#include <string>

#include "drivers/gps/nmea_parser.hpp"
#include "firmware/host/dataset/dataset_paths.hpp"
#include "firmware/host/dataset/diagnostic.hpp"
#include "firmware/host/dataset/meta_json.hpp"
#include "firmware/host/dataset/rate_tracker.hpp"

namespace sinu::dataset {

struct ImuSummary {
  RateTracker time;
  std::size_t accel_rows = 0, gyro_rows = 0, mag_rows = 0, temp_rows = 0;
  // Magnitudes, for a look at the units (replay checks them properly:
  // estimator/nav/sensor_scale_check.hpp): ~9.8 m/s^2, 22-67 uT on Earth.
  double sum_specific_force_m_s2 = 0.0, sum_field_uT = 0.0;
  double mean_specific_force_m_s2() const { return accel_rows ? sum_specific_force_m_s2 / static_cast<double>(accel_rows) : 0.0; }
  double mean_field_uT() const { return mag_rows ? sum_field_uT / static_cast<double>(mag_rows) : 0.0; }
  /// "" or what the magnitudes say about the units.
  std::string units_warning() const;
};

struct GpsSummary {
  std::uint64_t lines = 0, skipped_lines = 0;
  drivers::NmeaCounters sentences;
  std::uint64_t epochs = 0;
  RateTracker fixes;  // epochs with a usable position
  std::uint64_t fixes_with_sigma = 0;
  std::uint64_t fixes_without_height = 0;  // no GGA altitude: replay cannot use them
  std::uint64_t late_sentences = 0;  // after their epoch was emitted, or a repeated epoch time
  Diagnostic first_corrupt;  // empty message if none
};

struct TruthSummary {
  RateTracker time;
  std::size_t attitude_rows = 0;
};

struct DatasetSummary {
  std::string dir;
  ImuSummary imu;
  std::optional<GpsSummary> gps;
  std::optional<TruthSummary> truth;
  std::optional<Meta> meta;
};

/// False and `err` set at the first error in any file.
bool summarize_dataset(const DatasetPaths& paths, DatasetSummary& out, Diagnostic& err);

/// Human-readable and JSON renderings.
std::string format_summary(const DatasetSummary& s);
std::string format_summary_json(const DatasetSummary& s);

}  // namespace sinu::dataset
