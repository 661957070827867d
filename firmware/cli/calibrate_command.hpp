#pragma once
// `sinu calibrate`'s run, also the last step of `sinu bench`.
#include <cmath>
#include <string>
#include <vector>

namespace sinu::cli {

struct CalibrateOptions {
  std::vector<std::string> inputs;  // static dataset folders
  std::string out, report_dir, wavelet = "db4", model = "burg:3";
  int levels = 3;
  bool no_denoise = false, quiet = false;
  // Local gravity for a multi-position session (normal gravity formula); NaN: not given.
  double latitude_deg = NAN, height_m = NAN;
};

/// Fits the sessions and writes calib.json (and the report); an exit code, messages on stderr.
int run_calibrate(const CalibrateOptions& options);

}  // namespace sinu::cli
