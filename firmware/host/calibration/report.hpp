#pragma once
// `sinu calibrate --report DIR`: CSV tables of model against data plus
// report.md with the findings in plain sentences. PNG plots are drawn from
// the CSVs by tools/plot_calibration.py (host-only, matplotlib).
//   acf_s<k>_<axis>.csv     lag_s, measured, gm1, <method>_ar<p> (model autocorrelations)
//   allan_s<k>_<axis>.csv   tau_s, adev, adev_low, adev_high, model_adev
//   ar_variance.csv         session, axis, method, order, variance           (Figure 7)
//   ar_coefficients.csv     session, axis, method, order, index, value       (Tables 1-3)
//   gm_vs_ar.csv            GM1 against AR(p) variances                       (Table 4)
//   allan_terms.csv         session, axis, N, B, K, Q, R, B_tau_s
#include <string>

#include "firmware/host/calibration/calibration_run.hpp"

namespace sinu::calibration {

bool write_report(const CalibrationRun& run, const std::string& dir, std::string& why);

}  // namespace sinu::calibration
