#pragma once
// `sinu replay`: a dataset folder or a raw HAL recording (replay_source.hpp)
// through the Navigator, writing nav.csv, innovations.csv and summary.json
// into the output folder.
#include <string>

#include "firmware/replay/replay_options.hpp"

namespace sinu::replay {

struct ReplayTotals {
  std::uint64_t imu_samples = 0;
  double rmse_pos_h_m = 0.0;
  bool aligned = false;
  std::string note;  // from the source, e.g. "truncated: ..." ("" if nothing to say)
};

/// Returns true on success; false with a one-line `error` (file:line:column
/// where a file is at fault). Allocates a bounded number of times, independent
/// of the input's length.
bool run_replay(const ReplayOptions& options, ReplayTotals& totals, std::string& error);

}  // namespace sinu::replay
