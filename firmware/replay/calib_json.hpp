#pragma once
// calib.json (written by `sinu calibrate`, issue 5) -> the EKF's sensor noise.
// Keys read: axes.<ax|ay|az|gx|gy|gz>.gm {tau_s, variance};
// axes.<..>.ar.<method>[p-1] {a: [1, a1..ap], variance}; axes.<..>.allan.N
// (white-noise density, optional); the AR models' sample rate from
// "sample_rate_hz" at the top level or inside "denoiser" (default 40 Hz).
#include <string>

#include "estimator/ekf/sensor_noise.hpp"

namespace sinu::replay {

struct CalibChoice {
  est::NoiseModelKind kind = est::NoiseModelKind::AutoRegressive;
  std::string ar_method = "burg";
  int ar_order = 3;
};

/// Fills `noise`; false with `error` = "calib.json: <key>: <why>" otherwise.
bool load_calib(const std::string& path, const CalibChoice& choice, est::SensorNoise& noise, std::string& error);

}  // namespace sinu::replay
