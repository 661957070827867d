#pragma once
// calib.json: what `sinu calibrate` hands to the EKF (docs/calibration.md).
//   axes.<ax..gz>.gm            {tau_s, variance, driving_variance, ...}
//   axes.<..>.ar.<yule_walker|covariance|burg>  [p = 1..10] of {a: [1, a1..ap], variance}
//   axes.<..>.allan             {tau_s[], adev[], adev_low[], adev_high[], N, B, K, Q, R, ...}
//   axes.<..>.model             the model the EKF uses (default Burg AR(3))
//   axes.<..>.turn_on_bias, denoiser {name, wavelet, levels, sample_rate_hz}
// The first session fills `axes`; every session (with the first) is also in
// `sessions` for the cross-dataset comparison.
// A multi-position session adds "six_position" (six_position_run.hpp): the
// accelerometer's bias, scale and misalignment and the gyro bias, with sigmas.
#include <nlohmann/json.hpp>
#include <string>

#include "firmware/host/calibration/calibration_run.hpp"

namespace sinu::calibration {

nlohmann::json calibration_to_json(const CalibrationRun& run);

/// Writes the JSON; false with `why` if the file cannot be written.
bool write_calib_json(const CalibrationRun& run, const std::string& path, std::string& why);

}  // namespace sinu::calibration
