#pragma once
// The words and numbers of a diagnosis, shared by the printed summary,
// report.md and report.html: each sentence is built once, here.
#include <cstddef>
#include <string>
#include <vector>

#include "firmware/host/diagnose/diagnose_runner.hpp"

namespace sinu::diagnose {

/// One number through a printf format ("%.3g").
std::string format_number(const char* printf_format, double v);

/// "a, b, c" in vocabulary order, "none" if empty.
std::string effect_list(const est::EffectSet& s);

/// Component i of a candidate's estimate in its display unit: "8.939 +- 2.7".
std::string estimate_component_text(const CandidateResult& c, std::size_t i, const char* plus_minus = "+-");
/// The whole estimate with its unit: "[8.939 +- 2.7, -7.692 +- 1.2] mrad".
std::string estimate_text(const CandidateResult& c);

/// NIS per component ("1.02"), "-" without innovations.
std::string nis_cell(const ComponentStats& s);
/// "1.23 m", "n/a" for a negative value (no truth).
std::string rmse_text(double v, const char* unit);

/// The flight phase (with at least 50 components) where source k fits worst
/// relative to its flight average; kPhaseCount if none. `ratio`: phase NIS / average.
std::size_t worst_phase(const InnovationStats& s, std::size_t k, double& ratio);
/// The (source, phase) cell where the model fits worst, in words.
std::string worst_cell(const InnovationStats& s);

/// The noise levels diagnose tuned before comparing (magnetometer, GNSS
/// velocity): which sigma, how far off, what it was diagnosed with.
std::vector<std::string> tuned_noise_findings(const Diagnosis& d);
/// Without calib.json: the scale chosen for the built-in sensor model ("" if none).
std::string process_noise_text(const Diagnosis& d);
/// Without a calibration an effect named may stand for noise the built-in model lacks: said when one is.
std::string uncalibrated_text(const Diagnosis& d);

/// The candidate's name in tables: "lever_arm", or "lever_arm (re-learnt)"
/// for a model-file effect learnt again from its prior.
std::string candidate_name(const CandidateResult& c);
/// "gyro_misalign = [...] mrad (innovation log-likelihood +104.0, threshold 4.6)";
/// a changed one: "lever_arm has changed since the model file: [...] m, was [...] m (...)".
std::string missing_effect_text(const CandidateResult& c);
/// "gps_latency = 0.2348 +- 0.0031 s, assumed 0.05 s (60 sigma, 0.185 s off; ...)": a carried
/// effect this flight put far from the assumed value, with what to do (the option that sets it).
std::string carried_finding_text(const CarriedFinding& f);
/// A candidate the data want only at a size no real unit has: "gyro_misalign
/// would fit (log-likelihood +50.1) but only at 92 mrad, beyond the 35 mrad a real unit has: ...".
std::string implausible_fit_text(const CandidateResult& c);
/// implausible_fit_text of every such candidate, each effect once (the first round it appeared in).
std::vector<std::string> implausible_fits(const Diagnosis& d, double min_significance);
/// A bias that moved more than its calibrated walk (named or not: "" when not tested):
/// the sensor, the walk scale, the likelihood gain against its threshold and the best effect's.
std::string bias_walk_text(const BiasWalkFinding& w);
/// "" for a solution that stayed healthy; else "LOST at the end of the data (120 s)", "reset to
/// GNSS 3 time(s)", ...: a misfit that broke the solution, said before any figure of it.
std::string health_text(const SolutionHealth& h);
/// "" when the IMU measured throughout; else its clipped samples, gaps and
/// dropped samples, and that a misfit over them is no effect of the unit.
std::string imu_faults_text(const SolutionHealth& h);
/// "horizontal RMSE 2.1 m -> 0.9 m, attitude ...; NIS per component gnss_position 1.3 -> 1.0 ...".
std::string before_after_text(const Round& before, const Round& after);

/// The diagnosis in one sentence: the missing effect(s) with the error before
/// and after, or that no effect is missing (and whether the noise levels fit).
std::string conclusion_sentence(const Diagnosis& d);

}  // namespace sinu::diagnose
