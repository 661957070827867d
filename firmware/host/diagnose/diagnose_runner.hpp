#pragma once
// `sinu diagnose`: compare the model with the measurements, show where it
// fails, and name the missing physical effect.
//
// 1. Replay the data with the current model (baseline) and score it: per
//    aiding source and flight phase, the NIS of the innovations against the
//    filter's own sigmas (1 per component when the model is right), their
//    mean (a bias) and the rejections.
// 2. For each candidate effect in the vocabulary the EKF can estimate, replay
//    again with its states added; score the innovations' likelihood. An effect
//    that is really in the data makes the filter predict its measurements
//    better: the log-likelihood rises (a log Bayes factor: the states start
//    from their prior, so their cost is in it) beyond a decisive threshold,
//    and its estimate is many sigmas from zero.
// 3. Keep the best such effect, repeat (greedy) for a few rounds, and report
//    the sequence with the error before and after.
#include <algorithm>
#include <string>
#include <vector>

#include "estimator/ekf/state_layout.hpp"
#include "firmware/host/diagnose/innovation_series.hpp"
#include "firmware/host/diagnose/innovation_stats.hpp"
#include "firmware/host/replay/replay_options.hpp"
#include "firmware/host/replay/replay_result.hpp"

namespace sinu::diagnose {

struct DiagnoseOptions {
  replay::ReplayOptions replay;  // in_dir, calib, model, baseline effects
  std::string out_dir;           // report.md, report.html, diagnosis.json, baseline/ (the baseline replay's files)
  est::EffectSet candidates;     // tried one at a time
  int rounds = 2;
  double min_significance = 3.0;  // |estimate| / sigma of at least one component
  double min_log_evidence = 4.6;  // log Bayes factor: ln 100, "decisive" on Jeffreys' scale
  bool tune_noise_sigmas = true;  // scale the magnetometer, GNSS velocity and position sigmas by the baseline's NIS first
  bool tune_process_noise = true; // without calib.json: pick the default model's scale by likelihood
  std::string apply_path;         // non-empty: write the final model's effects there (a model file)
  unsigned threads = 0;           // candidate replays at once (0: one per core)
  bool progress = false;          // a line on stderr per candidate replay done
};

struct CandidateResult {
  est::Effect effect{};
  // A model-file effect learnt again from the vocabulary's prior (not the
  // file's value): named when this flight says it has changed since (an
  // antenna moved); its significance is then the distance from the file's value.
  bool changed = false;
  std::vector<double> file_estimate, file_sigma;  // the model file's value (changed candidates only)
  double nll_gain = 0.0;     // baseline NLL - NLL with the effect
  double evidence_threshold = 0.0;  // the log Bayes factor it must exceed (DiagnoseOptions::min_log_evidence)
  double significance = 0.0; // max |estimate - assumed value| / sigma
  std::vector<double> estimate, sigma;
  std::vector<double> sigma_ratio;  // per component: posterior / prior sigma (near 1: the flight did not reveal it)
  std::vector<bool> held;           // per component: its input never moved, held at the assumed value (NavUnitConfig::held)
  InnovationStats stats;
  double rmse_pos_h_m = -1.0, rmse_att_deg = -1.0;  // against truth.csv (-1: none)
  double plausibility = 0.0; // max |estimate| / the vocabulary's plausible maximum over the significant
                             // components: above 1 no real unit has it
  bool plausible() const { return plausibility <= 1.0; }
  /// The data want it (likelihood beyond the threshold, an estimate many sigmas
  /// from the assumed value) and a real unit can have it.
  bool explains(double min_significance) const {
    return nll_gain > evidence_threshold && significance >= min_significance && plausible();
  }
  /// The data want it but only at a size no real unit has: the misfit is something else.
  bool implausible_fit(double min_significance) const {
    return nll_gain > evidence_threshold && significance >= min_significance && !plausible();
  }
};

/// How the solution of one replay fared: its health, and the counters behind
/// it (resets, time lost, and what the IMU did not measure: clipped samples,
/// gaps, dropped samples).
struct SolutionHealth {
  replay::HealthStatus status = replay::HealthStatus::Ok;
  est::NavCounters counters;
};

struct Round {
  est::EffectSet model;             // the effects in the model this round starts from
  SolutionHealth health;            // its replay's
  est::EffectSet relearnt;          // model-file effects in it learnt again from their prior (found changed)
  InnovationStats stats;            // its score
  double rmse_pos_h_m = -1.0, rmse_att_deg = -1.0;
  double outage_drift_h_m = -1.0;   // RMS of the largest horizontal drift per --outage window (-1: none)
  std::vector<CandidateResult> candidates;  // best first
  bool found = false;               // candidates.front() explains the data
};

/// A bias that moved more than the calibration's random walk allows (a shift
/// in flight: a shock, a temperature step; or another unit than the one
/// calibrated). Not an effect: the baseline replayed with one sensor's
/// bias walk scaled, against the candidates' likelihood gains.
struct BiasWalkFinding {
  bool tested = false;     // a calib.json gave the walks
  bool gyro = false;       // the best trial's sensor (else the accelerometer)
  double scale = 1.0;      // its walk scale
  double nll_gain = 0.0;   // its log-likelihood gain over the baseline
  double threshold = 0.0;  // the gain it must exceed (scaled with the flight's length)
  double best_effect_gain = 0.0;  // the first round's best candidate's gain
  bool named = false;      // beyond the threshold and twice the best effect's gain
};

/// A property of the unit the model carries (EffectSpec::report_resolution:
/// the receiver's latency and the antenna's lever arm from their configured
/// values, the airframe's hard iron from zero) that this flight put far from
/// what was assumed. Not missing (its states followed it, the solution is not
/// hurt), but the user must learn it: named, and --apply writes it, so the
/// next flight starts from it (a heading right before the first turn).
struct CarriedFinding {
  est::Effect effect{};
  std::vector<double> assumed, estimate, sigma;  // assumed: the configured value, or 0 where none is configured
  double significance = 0.0;  // the largest |estimate - assumed| / sigma
  double deviation = 0.0;     // the largest |estimate - assumed| [state unit]
  /// A GPS latency learnt below zero (by its report resolution and 3 sigma:
  /// a receiver whose sentences arrive at the fix's instant learns zero give
  /// or take its noise): the fixes are valid after they arrive on the IMU's
  /// clock, which no receiver does; the IMU's samples are stamped late, by
  /// the assumed latency minus the learnt one (the receiver's own latency
  /// taken as configured) [s]. 0 otherwise.
  double imu_latency_s() const {
    if (effect != est::Effect::GpsLatency || estimate.empty() || sigma.empty()) return 0.0;
    const double below = std::max(3.0 * sigma[0], est::spec(effect).report_resolution);
    return estimate[0] < -below ? assumed[0] - estimate[0] : 0.0;
  }
};

/// The carried effects (a replay's `effects`: every state it had) with a
/// report_resolution whose estimate lies at least `min_significance` sigma and
/// that resolution from the assumed value; `skip`: effects named otherwise.
std::vector<CarriedFinding> carried_findings(const std::vector<replay::EffectEstimate>& effects,
                                             const est::EffectSet& skip, const DiagnoseOptions& o);

struct Diagnosis {
  double mag_sigma_uT = 0.0;         // the magnetometer sigma used (tuned from the baseline's NIS)
  double mag_sigma_given_uT = 0.0;   // as configured
  double vel_sigma_m_s = 0.0, vel_sigma_given_m_s = 0.0;  // GNSS velocity sigma, likewise
  double pos_sigma_scale = 1.0, pos_sigma_scale_given = 1.0;  // on the receiver's stated position sigma, likewise
  double process_noise_scale = 1.0;  // chosen by likelihood (1 with a calib.json)
  bool calibrated = false;           // the IMU's noise from a calib.json (a bench session of the unit)
  std::vector<Round> rounds;
  std::vector<est::Effect> missing;  // in the order found
  std::vector<est::Effect> changed;  // model-file effects this flight says have changed
  std::vector<CarriedFinding> carried;  // carried effects this flight puts far from the assumed value
  BiasWalkFinding bias_walk;
  bool model_changed() const { return !missing.empty() || !changed.empty() || bias_walk.named; }
  struct Skipped {
    est::Effect effect{};
    std::string reason;  // why the data cannot test it
  };
  std::vector<Skipped> skipped;           // candidates not tried
  std::vector<std::string> observability; // weakly observable components, and what would reveal them
  std::string model_file;                 // written by --apply ("" if not)
  std::vector<std::string> noise_findings;  // a source whose noise level the final model gets wrong, and by how much
  InnovationSeries baseline_innovations;    // the first round's replay over time (report.html's plots)
};

/// What the final model's NIS per source says of its noise levels: a source
/// whose innovations are larger (NIS > 1.3) or smaller (< 0.7) than its sigmas
/// claim, with the factor (sqrt NIS) and what sets that sigma.
std::vector<std::string> noise_findings(const InnovationStats& final_stats, bool effect_found);

/// Why this flight cannot test `effect` ("" if it can): no temperature, too
/// little temperature change, no magnetometer.
std::string untestable_reason(est::Effect effect, const replay::Excitation& x);

/// Fills c's estimate, sigmas, significance (the largest |estimate - assumed|
/// / sigma: the configured latency and lever arm, zero otherwise, the file's
/// value for a re-learnt effect) and plausibility (the largest significant
/// component against the vocabulary's plausible maximum) from a replay's
/// estimate of c.effect; `file` is the model file's value (c.changed only).
/// With the flight's excitation `x`, an accelerometer-driven component whose
/// input axis never spanned 0.1 g counts for neither.
void weigh_estimate(const replay::EffectEstimate& eff, const est::EffectPrior& file, const DiagnoseOptions& o,
                    CandidateResult& c, const replay::Excitation* x = nullptr);

/// Notes for the components of a candidate the flight barely constrained
/// (posterior sigma above half the prior), with what would reveal them.
void observability_notes(const CandidateResult& c, const replay::Excitation& x, std::vector<std::string>& out);

/// Runs the replays (in memory; the baseline's files under out_dir/baseline)
/// and writes report.md, report.html and diagnosis.json into out_dir. False with a one-line `error` on bad input.
bool run_diagnosis(const DiagnoseOptions& options, Diagnosis& out, std::string& error);

}  // namespace sinu::diagnose
