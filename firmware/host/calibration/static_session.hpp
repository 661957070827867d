#pragma once
// A static bench session (dataset folder with imu.csv) loaded as one series
// per axis for calibration. Rows missing an accelerometer or gyro triple are
// counted and skipped (the series stays evenly sampled apart from that, and
// the count is reported); the magnetometer, often slower, keeps only the rows
// where it has a value.
#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "firmware/host/dataset/diagnostic.hpp"

namespace sinu::calibration {

inline constexpr std::array<const char*, 6> kImuAxes = {"ax", "ay", "az", "gx", "gy", "gz"};
inline constexpr std::array<const char*, 3> kMagAxes = {"mx", "my", "mz"};

struct StaticSession {
  std::string dataset;                       // folder as given
  std::array<std::vector<double>, 6> imu;    // ax ay az [m/s^2], gx gy gz [rad/s]
  std::array<std::vector<double>, 3> mag;    // mx my mz [uT]
  double dt_s = 0.0;                         // mean sample interval
  double t0_s = 0.0;                         // t of the first row with accelerometer and gyro values
  double duration_s = 0.0;
  std::size_t rows = 0;
  std::size_t rows_without_imu = 0;          // skipped: a gyro reading before any accelerometer one
  std::size_t accel_held = 0;                // samples whose specific force an earlier row gave (dataset/imu_row_merger.hpp)
  std::size_t accel_interpolated = 0;        // samples whose specific force is interpolated between two rows'
  std::size_t gaps = 0;                      // intervals > 1.5 dt (lost samples)
};

/// Reads dataset/imu.csv completely. On false `err` names file, line and field.
/// `on_rows` (optional) is called every 100000 rows with the count so far.
bool load_static_session(const std::string& dataset, StaticSession& out, dataset::Diagnostic& err,
                         const std::function<void(std::size_t)>& on_rows = {});

/// Why the samples [begin, end) of a session (the part the noise models are
/// fitted on) are no bench data: a rate or a specific force that moved far
/// beyond any sensor noise (a flight given by mistake); "" when it held still.
std::string motion_in_session(const StaticSession& session, std::size_t begin, std::size_t end);

}  // namespace sinu::calibration
