#include "firmware/host/calibration/calibration_run.hpp"

#include <cmath>

#include "estimator/noise/mean_removal.hpp"

namespace sinu::calibration {

SessionCalibration calibrate_session(const StaticSession& session, const Denoiser& denoiser,
                                     const ModelChoice& model, const std::function<void()>& on_axis_done) {
  SessionCalibration s;
  s.dataset = session.dataset;
  s.sample_rate_hz = 1.0 / session.dt_s;
  s.duration_s = session.duration_s;
  s.rows = session.rows;
  s.rows_without_imu = session.rows_without_imu;
  s.gaps = session.gaps;
  AxisOptions opt;
  opt.dt_s = session.dt_s;
  opt.model = model;
  std::array<std::vector<double>, 6> denoised;
  for (std::size_t i = 0; i < kImuAxes.size(); ++i) {
    denoised[i] = denoiser.apply(session.imu[i], s.sample_rate_hz);
    s.axes[i] = calibrate_axis(kImuAxes[i], session.imu[i], denoised[i], opt);
    if (denoiser.detail_sigma) s.detail_sigma[i] = denoiser.detail_sigma(session.imu[i]);
    if (on_axis_done) on_axis_done();
  }
  s.model_rate = choose_model_rate(denoised, s.axes, session.dt_s, denoiser.levels);
  for (std::size_t i = 0; i < kMagAxes.size(); ++i) {
    double mean = 0.0;
    const std::vector<double> c = noise::remove_mean(session.mag[i], mean);
    double ss = 0.0;
    for (double v : c) ss += v * v;
    s.mag[i] = MagStatistics{mean, c.empty() ? 0.0 : std::sqrt(ss / static_cast<double>(c.size())), c.size()};
  }
  return s;
}

}  // namespace sinu::calibration
