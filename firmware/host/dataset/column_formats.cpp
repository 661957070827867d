#include "firmware/host/dataset/imu_csv.hpp"
#include "firmware/host/dataset/truth_csv.hpp"

namespace sinu::dataset {

namespace {
constexpr ColumnFormat kTime{ColumnFormat::Style::Fixed, 6};
}

void set_imu_formats(CsvWriter& w) {
  w.set_format(imu_col::t, kTime);
  for (std::size_t c = imu_col::ax; c < imu_col::count; ++c) w.set_format(c, {ColumnFormat::Style::Significant, 9});
}

void set_truth_formats(CsvWriter& w) {
  w.set_format(truth_col::t, kTime);
  w.set_format(truth_col::lat, {ColumnFormat::Style::Fixed, 9});
  w.set_format(truth_col::lon, {ColumnFormat::Style::Fixed, 9});
  for (std::size_t c : {truth_col::h, truth_col::vn, truth_col::ve, truth_col::vd})
    w.set_format(c, {ColumnFormat::Style::Fixed, 4});
  for (std::size_t c : {truth_col::roll, truth_col::pitch, truth_col::yaw}) w.set_format(c, {ColumnFormat::Style::Fixed, 6});
}

}  // namespace sinu::dataset
