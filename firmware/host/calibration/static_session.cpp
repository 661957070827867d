#include "firmware/host/calibration/static_session.hpp"

#include <cmath>

#include "firmware/host/dataset/dataset_paths.hpp"
#include "firmware/host/dataset/imu_csv.hpp"

namespace sinu::calibration {

namespace {
constexpr std::size_t kMinRows = 1000;      // below this no AR(10)/Allan fit means anything
constexpr double kGapFactor = 1.5;          // an interval this many dt long lost a sample
constexpr std::size_t kProgressEvery = 100000;
}  // namespace

bool load_static_session(const std::string& dataset, StaticSession& out, dataset::Diagnostic& err,
                         const std::function<void(std::size_t)>& on_rows) {
  out = StaticSession{};
  out.dataset = dataset;
  const dataset::DatasetPaths paths{dataset};
  dataset::CsvReader reader(dataset::kImuSchema);
  if (!reader.open(paths.imu())) {
    err = reader.error();
    return false;
  }
  dataset::ImuRow r;
  double t_first = 0.0, t_last = 0.0;
  std::vector<double> times;
  for (;;) {
    const dataset::ReadStatus st = reader.next(r.row);
    if (st == dataset::ReadStatus::Error) {
      err = reader.error();
      return false;
    }
    if (st == dataset::ReadStatus::End) break;
    ++out.rows;
    if (on_rows && out.rows % kProgressEvery == 0) on_rows(out.rows);
    if (!r.has_accel() || !r.has_gyro()) {
      ++out.rows_without_imu;
      continue;
    }
    const auto f = r.specific_force_b_m_s2();
    const auto w = r.angular_rate_b_rad_s();
    for (std::size_t i = 0; i < 3; ++i) {
      out.imu[i].push_back(f[i]);
      out.imu[3 + i].push_back(w[i]);
    }
    if (r.has_mag()) {
      const auto m = r.mag_b_uT();
      for (std::size_t i = 0; i < 3; ++i) out.mag[i].push_back(m[i]);
    }
    if (times.empty()) t_first = r.t_s();
    t_last = r.t_s();
    times.push_back(t_last);
  }
  const std::size_t n = out.imu[0].size();
  if (n < kMinRows) {
    err = dataset::Diagnostic{paths.imu(), 0, 0,
                         "a static session needs at least " + std::to_string(kMinRows) +
                             " rows with accelerometer and gyro values, found " + std::to_string(n)};
    return false;
  }
  out.t0_s = t_first;
  out.duration_s = t_last - t_first;
  out.dt_s = out.duration_s / static_cast<double>(n - 1);
  for (std::size_t i = 1; i < n; ++i) {
    if (times[i] - times[i - 1] > kGapFactor * out.dt_s) ++out.gaps;
  }
  return true;
}

}  // namespace sinu::calibration
