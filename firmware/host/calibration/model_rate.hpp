#pragma once
// AR models at the time scale that matters (issue 14). An AR(p) fitted to the
// denoised IMU-rate series describes the denoiser's band (poles at 0.2-0.6 s
// and at its 2.5-Hz cut-off), and forgets the error within a second; what an
// outage of tens of seconds needs is the slow error. The level-n wavelet
// approximation is band-limited, so it may be decimated: its block means at
// fs / 2^n (5 Hz for 40 Hz, level 3) and slower rates are fitted with the same
// three methods, and the rate is chosen by what the model predicts where it
// matters: each candidate model's Allan deviation (with the white noise N of
// the Allan fit added, as the EKF carries it) against the measured one over
// 1-100 s, the score being the RMS of ln(model / measured) over the six axes
// and the measured averaging times in that span. The IMU rate is a candidate
// too, so the choice is never worse than the fit at the IMU rate by this
// criterion. The EKF propagates the chosen rate's AR states every k-th IMU
// sample (SensorNoise::ar_sample_period_s).
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "firmware/host/calibration/axis_calibration.hpp"

namespace sinu::calibration {

struct RateScore {
  double rate_hz = 0.0;
  std::size_t decimation = 1;  // IMU samples per model step
  double score = 0.0;          // RMS of ln(ADEV model / ADEV measured) over 1-100 s and the axes; +inf: unusable
};

/// One axis at the chosen rate: its AR fits, and the Allan deviation measured
/// and predicted by GM1, by the chosen AR at the IMU rate and at the model rate.
struct AxisAtRate {
  std::array<std::vector<noise::ArModel>, kArMethods> ar;  // [method][p-1]
  std::vector<double> tau_s, adev_measured, adev_gm, adev_ar_imu, adev_ar_model;
};

struct ModelRate {
  double rate_hz = 0.0;
  std::size_t decimation = 1;
  std::vector<RateScore> candidates;
  std::array<AxisAtRate, 6> axes;
  bool valid() const { return rate_hz > 0.0; }
};

/// `denoised[i]` is axis i's denoised series (IMU rate, mean included), `axes`
/// the IMU-rate calibration of the same series (its Allan deviation, N, GM1).
ModelRate choose_model_rate(const std::array<std::vector<double>, 6>& denoised,
                            const std::array<AxisCalibration, 6>& axes, double dt_s, int denoiser_levels);

/// The Allan deviation an AR model sampled every dt_s predicts at tau_s, white noise of density N added.
double ar_model_adev(const noise::ArModel& model, double dt_s, double tau_s, double white_density);
/// The same for GM1 (closed form) with white noise N added.
double gm_model_adev(const noise::GaussMarkov1& gm, double tau_s, double white_density);

}  // namespace sinu::calibration
