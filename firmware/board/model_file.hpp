#pragma once
// The model file: effects a unit is known to have, with their values and
// sigmas, so a flight starts from what an earlier one found. `sinu diagnose
// --apply` writes it; `replay`, `diagnose` (--model-file) and `fly`
// (navigation.model_file) read it.
//   {"effects": {"gyro_misalign": {"estimate": [6 numbers], "sigma": [6 numbers]},
//                "gps_latency": {"estimate": [0.21], "sigma": [0.004]}, ...},
//    "imu_latency_s": 0.12,   (optional: the IMU's samples stamped that late)
//    "source": "what wrote it"}
// Estimates are in the estimator's state units (effect_vocabulary.hpp: scale
// [-], misalignment [rad], g-sensitivity [rad/s per m/s^2], ...), components
// in its order.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "estimator/ekf/effect_tuning.hpp"

namespace sinu::board {

struct ModelEffect {
  est::Effect effect{};
  std::vector<double> estimate, sigma;
};

/// Reads `path`: adds its effects to `effects` and their priors to `priors`.
/// False with `error` naming the file and the key on any problem.
/// Its imu_latency_s, when it has one, into `imu_latency_s` (left as is otherwise).
bool read_model_file(const std::string& path, est::EffectSet& effects,
                     std::array<est::EffectPrior, est::kEffectCount>& priors, double& imu_latency_s,
                     std::string& error);

/// `path` parsed (a discarded value when it is not JSON); false with `error`
/// when it cannot be opened.
bool parse_json_file(const std::string& path, nlohmann::json& j, std::string& error);
/// read_model_file's reading of an already parsed file (`path` for the errors).
bool read_model_json(const nlohmann::json& j, const std::string& path, est::EffectSet& effects,
                     std::array<est::EffectPrior, est::kEffectCount>& priors, double& imu_latency_s,
                     std::string& error);

/// The IMU latency a flight runs with: the configured one, else the model file's.
inline double imu_latency_in_use(double configured_s, double model_file_s) {
  return configured_s > 0.0 ? configured_s : model_file_s;
}

/// The model file's JSON (what write_model_file writes): a state file
/// (state_file.hpp) is one with more keys.
nlohmann::json model_json(const std::vector<ModelEffect>& effects, double imu_latency_s, const std::string& source);

/// Writes `j` to `path` whole or not at all (a temporary file renamed over it:
/// a power cut leaves the old file). False with `error` naming the file.
bool write_json_file(const std::string& path, const nlohmann::json& j, std::string& error);

/// Writes the effects (estimates and sigmas) as a model file, and the IMU's
/// latency when it is above zero.
bool write_model_file(const std::string& path, const std::vector<ModelEffect>& effects, double imu_latency_s,
                      const std::string& source, std::string& error);

}  // namespace sinu::board
