#pragma once
// Everything `sinu replay` needs, parsed and validated by the CLI: where the
// samples come from, the navigation unit to build, and how the GPS is thinned
// (slower updates, outages) for the paper's experiments.
#include <string>
#include <vector>

#include "drivers/imu/icm20948.hpp"
#include "firmware/board/nav_unit_config.hpp"

namespace sinu::replay {

struct Outage {
  double start_s = 0.0;     // dataset time t
  double duration_s = 0.0;
};

struct ReplayOptions {
  std::string in_dir;       // dataset folder or raw recording file
  std::string truth_path;   // truth.csv; empty: the dataset folder's, if any
  drivers::Icm20948Config imu;  // driver settings for a raw recording (as `sinu convert`)
  board::NavUnitConfig unit;
  double gps_period_s = 0.0;  // 0: every epoch
  double gps_period_from_s = -1e300;  // the slower GPS from this dataset time on (every epoch before)
  std::vector<Outage> outages;
};

/// Parses "START:DURATION,START:DURATION"; false with `error` on bad input.
bool parse_outages(const std::string& text, std::vector<Outage>& out, std::string& error);

}  // namespace sinu::replay
