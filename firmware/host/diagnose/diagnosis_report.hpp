#pragma once
// The diagnosis in words and numbers: report.md (for a person) and
// diagnosis.json (for scripts) in the diagnose output folder, and the short
// text the CLI prints.
#include <string>

#include "firmware/host/diagnose/diagnose_runner.hpp"

namespace sinu::diagnose {

bool write_diagnosis(const DiagnoseOptions& options, const Diagnosis& d, std::string& error);

/// A few lines: where the baseline fails, the missing effect(s) and the error before and after.
std::string diagnosis_summary(const DiagnoseOptions& options, const Diagnosis& d);

}  // namespace sinu::diagnose
