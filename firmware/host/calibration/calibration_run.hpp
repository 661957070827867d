#pragma once
// A calibration run: one or more static sessions, each calibrated per axis.
// The first session is the calibration the EKF uses; the others are the
// paper's cross-dataset comparison (coefficient consistency, Tables 1-3).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "firmware/host/calibration/axis_calibration.hpp"
#include "firmware/host/calibration/denoiser.hpp"
#include "firmware/host/calibration/model_rate.hpp"
#include "firmware/host/calibration/six_position.hpp"
#include "firmware/host/calibration/static_session.hpp"

namespace sinu::calibration {

struct MagStatistics {
  double mean_uT = 0.0, std_uT = 0.0;
  std::size_t samples = 0;
};

struct SessionCalibration {
  std::string dataset;
  double sample_rate_hz = 0.0;
  double duration_s = 0.0;
  std::size_t rows = 0, rows_without_imu = 0, gaps = 0;
  std::array<AxisCalibration, 6> axes;
  ModelRate model_rate;  // the AR models at the rate their Allan deviation fits best (model_rate.hpp)
  std::array<std::vector<double>, 6> detail_sigma;  // per axis, the noise in the denoiser's details per level (none: empty)
  std::array<MagStatistics, 3> mag;
};

struct CalibrationRun {
  Denoiser denoiser;
  std::vector<SessionCalibration> sessions;
  std::optional<SixPositionCalibration> six_position;  // a session held in several attitudes
};

/// Calibrates one loaded session. `on_axis_done` (optional) after each axis.
SessionCalibration calibrate_session(const StaticSession& session, const Denoiser& denoiser,
                                     const ModelChoice& model, const std::function<void()>& on_axis_done = {});

/// Plain sentences where the models fail to describe the data (report).
std::vector<std::string> findings(const AxisCalibration& axis, double dt_s);

}  // namespace sinu::calibration
