#include "firmware/host/diagnose/diagnose_runner.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "firmware/host/diagnose/diagnosis_report.hpp"
#include "firmware/host/replay/replay_files.hpp"

namespace sinu::diagnose {

namespace {

struct RunScore {
  InnovationStats stats;
  double rmse_pos_h_m = -1.0, rmse_att_deg = -1.0;
  std::vector<replay::EffectEstimate> effects;
};

double or_minus_one(double v) { return std::isfinite(v) ? v : -1.0; }

/// One replay with `effects`, scored in memory; with `files_dir`, its nav.csv,
/// innovations.csv and summary.json are written there too.
bool replay_and_score(replay::ReplayOptions opt, est::EffectSet effects, const std::string& files_dir, RunScore& out,
                      std::string& error) {
  opt.unit.effects = effects;
  InnovationStatsListener stats;
  replay::ReplayListener* const listeners[] = {&stats};
  replay::ReplayResult result;
  const bool ok = files_dir.empty() ? replay::run_replay(opt, listeners, result, error, false)
                                    : replay::replay_to_folder(opt, files_dir, 10.0, result, error, listeners, false);
  if (!ok) return false;
  out.stats = stats.stats();
  out.rmse_pos_h_m = or_minus_one(result.rmse_pos_h_m());
  out.rmse_att_deg = or_minus_one(result.rmse_att_deg());
  out.effects = result.effects;
  return true;
}

std::uint64_t innovation_count(const InnovationStats& s) {
  std::uint64_t n = 0;
  for (const ComponentStats& c : s.source) n += c.count;
  return n;
}

}  // namespace

bool run_diagnosis(const DiagnoseOptions& o, Diagnosis& out, std::string& error) {
  namespace fs = std::filesystem;
  out = {};
  std::error_code ec;
  fs::create_directories(o.out_dir, ec);
  est::EffectSet model = o.replay.unit.effects;
  RunScore current;
  const std::string baseline_dir = (fs::path(o.out_dir) / "baseline").string();
  DiagnoseOptions tuned = o;
  if (!replay_and_score(tuned.replay, model, baseline_dir, current, error)) return false;
  out.mag_sigma_given_uT = out.mag_sigma_uT = o.replay.unit.mag_sigma_uT;
  out.vel_sigma_given_m_s = out.vel_sigma_m_s = o.replay.unit.sigma.velocity_sigma_m_s;
  // The magnetometer's and the GNSS velocity's sigmas are guesses (GST reports
  // only the position's). A too-generous sigma hides effects: when a source's
  // NIS per component is below 0.5, scale its sigma by sqrt(NIS) (the factor
  // for white noise) so it is 1. Never upwards: a NIS above 1 is what a
  // missing effect looks like, and inflating the sigma would hide it.
  const double mag_nis = current.stats.source[2].nis(), vel_nis = current.stats.source[1].nis();
  const bool tune_mag = current.stats.source[2].count > 100 && mag_nis < 0.5;
  const bool tune_vel = current.stats.source[1].count > 100 && vel_nis < 0.5;
  if (o.tune_mag_sigma && (tune_mag || tune_vel)) {
    if (tune_mag) tuned.replay.unit.mag_sigma_uT = out.mag_sigma_uT = std::max(0.05, o.replay.unit.mag_sigma_uT * std::sqrt(mag_nis));
    if (tune_vel) {
      tuned.replay.unit.sigma.velocity_sigma_m_s = out.vel_sigma_m_s =
          std::max(0.01, o.replay.unit.sigma.velocity_sigma_m_s * std::sqrt(vel_nis));
    }
    if (!replay_and_score(tuned.replay, model, baseline_dir, current, error)) return false;
  }
  // Without a calibration the built-in sensor model is a generic guess, usually
  // far too loose for a given unit: a loose model hides effects. Choose the
  // scale of its coloured-error variances by maximum likelihood of the
  // innovations (the same criterion that then judges the candidates).
  out.process_noise_scale = 1.0;
  if (o.tune_process_noise && o.replay.unit.calib_path.empty()) {
    for (const double scale : {0.3, 0.1, 0.03, 0.01}) {
      DiagnoseOptions trial = tuned;
      trial.replay.unit.process_noise_scale = scale;
      RunScore score;
      if (!replay_and_score(trial.replay, model, "", score, error)) return false;
      if (score.stats.total_nll() >= current.stats.total_nll()) break;  // the likelihood has peaked
      current = std::move(score);
      tuned = trial;
      out.process_noise_scale = scale;
    }
  }
  for (int r = 0; r < o.rounds; ++r) {
    Round round;
    round.model = model;
    round.stats = current.stats;
    round.rmse_pos_h_m = current.rmse_pos_h_m;
    round.rmse_att_deg = current.rmse_att_deg;
    const double ln_n = std::log(std::max<double>(2.0, static_cast<double>(innovation_count(current.stats))));
    std::vector<RunScore> scores;
    for (std::size_t e = 0; e < est::kEffectCount; ++e) {
      const auto effect = static_cast<est::Effect>(e);
      if (!o.candidates.has(effect) || model.has(effect)) continue;
      est::EffectSet trial = model;
      trial.add(effect);
      RunScore score;
      if (!replay_and_score(tuned.replay, trial, "", score, error)) return false;
      CandidateResult c;
      c.effect = effect;
      c.nll_gain = current.stats.total_nll() - score.stats.total_nll();
      c.penalty = 0.5 * static_cast<double>(est::kEffectDims[e]) * ln_n;
      for (const replay::EffectEstimate& eff : score.effects) {
        if (eff.effect != effect) continue;
        for (std::size_t i = 0; i < eff.estimate.size(); ++i) {
          const double v = eff.estimate[i], s = eff.sigma[i];
          c.estimate.push_back(v);
          c.sigma.push_back(s);
          // Distance from what the model assumed without the states (the configured latency
          // and lever arm, zero otherwise), in sigmas.
          double prior = 0.0;
          if (effect == est::Effect::GpsLatency) prior = o.replay.unit.gps_latency_s;
          if (effect == est::Effect::LeverArm) prior = o.replay.unit.lever_arm_b_m(static_cast<Eigen::Index>(i));
          if (s > 0.0) c.significance = std::max(c.significance, std::abs(v - prior) / s);
        }
      }
      c.stats = score.stats;
      c.rmse_pos_h_m = score.rmse_pos_h_m;
      c.rmse_att_deg = score.rmse_att_deg;
      round.candidates.push_back(c);
      scores.push_back(std::move(score));
    }
    // Best first: those that explain the data, by likelihood gain beyond the penalty.
    std::vector<std::size_t> order(round.candidates.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    auto rank = [&](std::size_t i) {
      const CandidateResult& c = round.candidates[i];
      return (c.explains(o.min_significance) ? 1e12 : 0.0) + c.nll_gain - c.penalty;
    };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank(a) > rank(b); });
    std::vector<CandidateResult> sorted;
    for (std::size_t i : order) sorted.push_back(round.candidates[i]);
    round.candidates = sorted;
    round.found = !round.candidates.empty() && round.candidates.front().explains(o.min_significance);
    if (round.found) {
      model.add(round.candidates.front().effect);
      out.missing.push_back(round.candidates.front().effect);
      current = std::move(scores[order.front()]);
    }
    out.rounds.push_back(std::move(round));
    if (!out.rounds.back().found) break;
  }
  // The final model's score, for the "after" column.
  Round last;
  last.model = model;
  last.stats = current.stats;
  last.rmse_pos_h_m = current.rmse_pos_h_m;
  last.rmse_att_deg = current.rmse_att_deg;
  if (out.rounds.empty() || out.rounds.back().found) out.rounds.push_back(last);
  return write_diagnosis(tuned, out, error);
}

}  // namespace sinu::diagnose
