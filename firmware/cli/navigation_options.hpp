#pragma once
// The navigation options `sinu replay` and `sinu diagnose` share: input,
// truth, calibration and model, effect states, GPS and magnetometer set-up,
// and the driver settings of a raw recording. One definition, so both modes
// accept the same words with the same meaning.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "firmware/cli/board_options.hpp"
#include "firmware/host/replay/replay_options.hpp"

namespace sinu::cli {

struct NavigationCliOptions {
  replay::ReplayOptions opt;
  std::string model;
  std::string effects;          // added to the defaults
  std::string without_effects;  // removed from them
  std::string vehicle = "auto";
  std::vector<double> lever_arm;
  BoardOptions imu;  // for a raw recording: the driver settings it was recorded with
  CLI::App* app = nullptr;

  NavigationCliOptions(std::string default_model, std::string default_effects)
      : model(std::move(default_model)), effects(std::move(default_effects)) {}
  /// Adds the shared options to `sub` (this object must outlive the parse).
  void add_to(CLI::App& sub);
  /// Checks and converts model, effects, lever arm and driver settings into
  /// `opt`; false with `error` (a usage error) otherwise.
  bool resolve(std::string& error);
};

}  // namespace sinu::cli
