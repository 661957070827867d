#pragma once
// Which effect states the EKF carries: the defaults every model starts from,
// and the words users add or remove them with (command line, sinu.toml).
#include <string>

#include "estimator/ekf/state_layout.hpp"

namespace sinu::board {

/// The effect states every model carries unless removed explicitly: the
/// unit's turn-on biases (a calibration's GM/AR models are zero-mean), the
/// receiver's slowly varying position error (GST's sigma split into it and
/// white noise) and its latency (NMEA arrives some tens of ms after the fix).
est::EffectSet default_effects();

/// Parses "accel_scale,lever_arm"; false with `error` naming the bad effect.
bool parse_effects(const std::string& text, est::EffectSet& out, std::string& error);
/// The defaults, plus `added`, minus `removed` (both comma lists; "none" removes all defaults).
bool resolve_effects(const std::string& added, const std::string& removed, est::EffectSet& out, std::string& error);

}  // namespace sinu::board
