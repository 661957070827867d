#pragma once
// imu.csv: t,ax,ay,az,gx,gy,gz,mx,my,mz,temp (dataset-format.md).
// ax..az specific force [m/s^2], gx..gz angular rate [rad/s], both body FRD;
// mx..mz magnetic flux density [uT]; temp die temperature [degC].
#include <array>
#include <string_view>

#include "firmware/host/dataset/csv_table.hpp"

namespace sinu::dataset {

namespace imu_col {
enum : std::size_t { t, ax, ay, az, gx, gy, gz, mx, my, mz, temp, count };
}

inline constexpr std::array<std::string_view, imu_col::count> kImuColumns = {
    "t", "ax", "ay", "az", "gx", "gy", "gz", "mx", "my", "mz", "temp"};
// An IMU samples at 10 Hz or faster; 1 s between samples is already no IMU.
inline constexpr CsvSchema kImuSchema{"imu.csv", kImuColumns, 1.0};

/// Named view of one imu.csv row.
struct ImuRow {
  CsvRow row;
  double t_s() const { return row.value[imu_col::t]; }
  bool has_accel() const { return all(imu_col::ax); }
  bool has_gyro() const { return all(imu_col::gx); }
  bool has_mag() const { return all(imu_col::mx); }
  bool has_temp() const { return row.has(imu_col::temp); }
  std::array<double, 3> specific_force_b_m_s2() const { return triple(imu_col::ax); }
  std::array<double, 3> angular_rate_b_rad_s() const { return triple(imu_col::gx); }
  std::array<double, 3> mag_b_uT() const { return triple(imu_col::mx); }
  double temp_degC() const { return row.value[imu_col::temp]; }

 private:
  bool all(std::size_t first) const { return row.has(first) && row.has(first + 1) && row.has(first + 2); }
  std::array<double, 3> triple(std::size_t first) const {
    return {row.value[first], row.value[first + 1], row.value[first + 2]};
  }
};

/// Column formats the project's writers use: t to the microsecond, sensor
/// values to 9 significant digits (well below any MEMS quantisation step).
void set_imu_formats(CsvWriter& writer);

}  // namespace sinu::dataset
