#pragma once
// truth.csv: t,lat,lon,h,vn,ve,vd,roll,pitch,yaw (dataset-format.md).
// lat/lon [deg] WGS-84 of the IMU, h [m] ellipsoidal, v NED [m/s],
// Euler ZYX [deg] of body FRD w.r.t. NED, yaw in [-180, 180).
#include <array>
#include <string_view>

#include "firmware/host/dataset/csv_table.hpp"

namespace sinu::dataset {

namespace truth_col {
enum : std::size_t { t, lat, lon, h, vn, ve, vd, roll, pitch, yaw, count };
}

inline constexpr std::array<std::string_view, truth_col::count> kTruthColumns = {
    "t", "lat", "lon", "h", "vn", "ve", "vd", "roll", "pitch", "yaw"};
inline constexpr CsvSchema kTruthSchema{"truth.csv", kTruthColumns};

/// lat/lon to 1e-9 deg (0.1 mm), heights and velocities to 0.1 mm(/s),
/// angles to 1e-6 deg; t to the microsecond.
void set_truth_formats(CsvWriter& writer);

}  // namespace sinu::dataset
