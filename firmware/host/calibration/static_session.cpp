#include "firmware/host/calibration/static_session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "firmware/host/dataset/dataset_paths.hpp"
#include "firmware/host/dataset/imu_csv.hpp"
#include "firmware/host/dataset/imu_row_merger.hpp"
#include "firmware/host/dataset/quantile.hpp"

namespace sinu::calibration {

namespace {
constexpr std::size_t kMinRows = 1000;      // below this no AR(10)/Allan fit means anything
constexpr double kGapFactor = 1.5;          // an interval this many dt long lost a sample
constexpr std::size_t kProgressEvery = 100000;
// A bench session's 1st-99th percentile span per axis is a few sigma of
// noise: 0.01 rad/s and 0.06-0.08 m/s^2 for the simulator's consumer MEMS at
// 40 Hz. A flight spans tenths of rad/s and m/s^2 and more (a simulated
// flight 0.37 rad/s and 2.4 m/s^2, the real quadcopter 2.3 rad/s and 5.9
// m/s^2, the real car 1.0 rad/s and 5.9 m/s^2): 10x a bench's noise, 0.1
// rad/s (5.7 deg/s) and 1 m/s^2, is motion, and leaves room for a noisier
// unit or a faster rate.
constexpr double kMaxStillRateSpan_rad_s = 0.1, kMaxStillForceSpan_m_s2 = 1.0;

/// The 1st to 99th percentile span of x[begin, end).
double percentile_span(const std::vector<double>& x, std::size_t begin, std::size_t end) {
  end = std::min(end, x.size());
  if (end < begin + 100) return 0.0;  // too few samples to call anything motion
  const std::vector<double> v(x.begin() + static_cast<std::ptrdiff_t>(begin), x.begin() + static_cast<std::ptrdiff_t>(end));
  return dataset::quantile(v, 0.99) - dataset::quantile(v, 0.01);
}
}  // namespace

std::string motion_in_session(const StaticSession& s, std::size_t begin, std::size_t end) {
  for (std::size_t k = 0; k < kImuAxes.size(); ++k) {
    const bool gyro = k >= 3;
    const double span = percentile_span(s.imu[k], begin, end);
    const double limit = gyro ? kMaxStillRateSpan_rad_s : kMaxStillForceSpan_m_s2;
    if (span > limit)
      return fmt::format("{} spans {:.3g} {} (1st to 99th percentile) where a unit at rest spans a few times its noise "
                         "(limit {:g}): the unit moved; calibrate needs a bench session held still (or in several "
                         "held attitudes), not a flight",
                         kImuAxes[k], span, gyro ? "rad/s" : "m/s^2", limit);
  }
  return "";
}

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
  dataset::ImuRowMerger merger;  // rows with part of the IMU into samples
  double t_first = 0.0, t_last = 0.0;
  std::vector<double> times;
  const auto take = [&](const est::ImuSample& s) {
    for (Eigen::Index i = 0; i < 3; ++i) {
      const auto k = static_cast<std::size_t>(i);
      out.imu[k].push_back(s.specific_force_b_m_s2(i));
      out.imu[3 + k].push_back(s.angular_rate_b_rad_s(i));
      if (s.has_mag) out.mag[k].push_back(s.mag_b_uT(i));
    }
    if (times.empty()) t_first = s.t_s;
    t_last = s.t_s;
    times.push_back(t_last);
  };
  est::ImuSample s;
  for (;;) {
    const dataset::ReadStatus st = reader.next(r.row);
    if (st == dataset::ReadStatus::Error) {
      err = reader.error();
      return false;
    }
    if (st == dataset::ReadStatus::End) break;
    ++out.rows;
    if (on_rows && out.rows % kProgressEvery == 0) on_rows(out.rows);
    merger.add(r);
    while (merger.next(s)) take(s);
  }
  merger.finish();
  while (merger.next(s)) take(s);
  out.rows_without_imu = merger.counts().left_out;
  out.accel_held = merger.counts().accel_held;
  out.accel_interpolated = merger.counts().accel_interpolated;
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
