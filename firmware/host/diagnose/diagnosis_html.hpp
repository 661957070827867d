#pragma once
// report.html: the diagnosis as one self-contained page (inline SVG, a small
// inline script for zooming the time axis, no external reference), top to
// bottom: the conclusion, the baseline's innovations over time with their
// sigma bands and the flight phases shaded, the NIS per source and phase, each
// candidate's evidence, the error before and after, the noise findings.
#include <string>

#include "firmware/host/diagnose/diagnose_runner.hpp"

namespace sinu::diagnose {

/// The page.
std::string diagnosis_html(const DiagnoseOptions& options, const Diagnosis& d);

/// Writes diagnosis_html to out_dir/report.html; false with `error` if it cannot.
bool write_diagnosis_html(const DiagnoseOptions& options, const Diagnosis& d, std::string& error);

}  // namespace sinu::diagnose
