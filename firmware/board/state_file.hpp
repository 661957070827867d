#pragma once
// The state file: what the running unit has learnt (est::WarmStart), written
// every few seconds so that a unit restarted in the air (the companion
// computer rebooted) starts from it instead of from nothing. It is a model
// file (model_file.hpp: the effects with estimates and sigmas) with more keys:
//   {"effects": {...}, "saved_utc_ms": 1700000000000,
//    "temp_ref_degC": 31.2, "gps_bias_level_ned_m": [n, e, d],
//    "gnss_velocity_sigma_m_s": 0.1, "mag_sigma_uT": 0.8,
//    "gnss_white_scale": [h, v], "gnss_position_scale": [h, v],
//    "vehicle": {"guess": "ground", "on_bracket": false, "lateral_b": [0, 1, 0], "vertical_b": [0, 0, 1]},
//    "source": "..."}
// ("vehicle" only while the detector holds the unit on a ground vehicle.)
// saved_utc_ms (GNSS time of the solution, ms since 1970) dates it: a restart
// uses it only while it is younger than a bound (NavUnitConfig::state_max_age_s).
#include <cstdint>
#include <string>

#include "estimator/nav/warm_start.hpp"

namespace sinu::board {

struct SavedState {
  est::WarmStart warm;
  std::int64_t saved_utc_ms = 0;
};

/// False with `error` naming the file and the key at fault.
bool read_state_file(const std::string& path, SavedState& out, std::string& error);
bool write_state_file(const std::string& path, const SavedState& state, std::string& error);

}  // namespace sinu::board
