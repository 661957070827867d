#include "firmware/diagnose/diagnose_runner.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "firmware/diagnose/diagnosis_report.hpp"
#include "firmware/replay/replay_runner.hpp"

namespace sinu::diag {

namespace {

struct RunScore {
  InnovationStats stats;
  double rmse_pos_h_m = -1.0, rmse_att_deg = -1.0;
  nlohmann::json effects;
};

double number_or(const nlohmann::json& j, const char* key, double fallback) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : fallback;
}

bool replay_and_score(replay::ReplayOptions opt, est::EffectSet effects, const std::string& dir, RunScore& out,
                      std::string& error) {
  opt.effects = effects;
  opt.out_dir = dir;
  opt.quiet = true;
  replay::ReplayTotals totals;
  if (!replay::run_replay(opt, totals, error)) return false;
  if (!read_innovation_stats(dir, out.stats, error)) return false;
  std::ifstream in(dir + "/summary.json");
  const nlohmann::json s = nlohmann::json::parse(in, nullptr, false);
  if (s.is_discarded()) {
    error = dir + "/summary.json: not valid JSON";
    return false;
  }
  out.rmse_pos_h_m = number_or(s["rmse"], "pos_h_m", -1.0);
  out.rmse_att_deg = number_or(s["rmse"], "att_deg", -1.0);
  out.effects = s["effects"];
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
  fs::create_directories(o.replay.out_dir, ec);
  est::EffectSet model = o.replay.effects;
  RunScore current;
  const std::string baseline_dir = (fs::path(o.replay.out_dir) / "baseline").string();
  DiagnoseOptions tuned = o;
  if (!replay_and_score(tuned.replay, model, baseline_dir, current, error)) return false;
  out.mag_sigma_given_uT = out.mag_sigma_uT = o.replay.mag_sigma_uT;
  out.vel_sigma_given_m_s = out.vel_sigma_m_s = o.replay.sigma.velocity_sigma_m_s;
  // The magnetometer's and the GNSS velocity's sigmas are guesses (GST reports
  // only the position's). A too-generous sigma hides effects: when a source's
  // NIS per component is below 0.5, scale its sigma by sqrt(NIS) (the factor
  // for white noise) so it is 1. Never upwards: a NIS above 1 is what a
  // missing effect looks like, and inflating the sigma would hide it.
  const double mag_nis = current.stats.source[2].nis(), vel_nis = current.stats.source[1].nis();
  const bool tune_mag = current.stats.source[2].count > 100 && mag_nis < 0.5;
  const bool tune_vel = current.stats.source[1].count > 100 && vel_nis < 0.5;
  if (o.tune_mag_sigma && (tune_mag || tune_vel)) {
    if (tune_mag) tuned.replay.mag_sigma_uT = out.mag_sigma_uT = std::max(0.05, o.replay.mag_sigma_uT * std::sqrt(mag_nis));
    if (tune_vel) {
      tuned.replay.sigma.velocity_sigma_m_s = out.vel_sigma_m_s =
          std::max(0.01, o.replay.sigma.velocity_sigma_m_s * std::sqrt(vel_nis));
    }
    if (!replay_and_score(tuned.replay, model, baseline_dir, current, error)) return false;
  }
  // Without a calibration the built-in sensor model is a generic guess, usually
  // far too loose for a given unit: a loose model hides effects. Choose the
  // scale of its coloured-error variances by maximum likelihood of the
  // innovations (the same criterion that then judges the candidates).
  out.process_noise_scale = 1.0;
  if (o.tune_process_noise && o.replay.calib_path.empty()) {
    for (const double scale : {0.3, 0.1, 0.03, 0.01}) {
      DiagnoseOptions trial = tuned;
      trial.replay.process_noise_scale = scale;
      RunScore score;
      const std::string dir = (fs::path(o.replay.out_dir) / "noise_scale" / std::to_string(scale)).string();
      if (!replay_and_score(trial.replay, model, dir, score, error)) return false;
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
      const std::string dir =
          (fs::path(o.replay.out_dir) / ("round" + std::to_string(r + 1)) / est::kEffectNames[e]).string();
      RunScore score;
      if (!replay_and_score(tuned.replay, trial, dir, score, error)) return false;
      CandidateResult c;
      c.effect = effect;
      c.nll_gain = current.stats.total_nll() - score.stats.total_nll();
      c.penalty = 0.5 * static_cast<double>(est::kEffectDims[e]) * ln_n;
      for (const auto& eff : score.effects) {
        if (eff["name"] != est::kEffectNames[e]) continue;
        for (std::size_t i = 0; i < eff["estimate"].size(); ++i) {
          const double v = eff["estimate"][i].get<double>(), s = eff["sigma"][i].get<double>();
          c.estimate.push_back(v);
          c.sigma.push_back(s);
          // Distance from what the model assumed without the states (the configured latency
          // and lever arm, zero otherwise), in sigmas.
          double prior = 0.0;
          if (effect == est::Effect::GpsLatency) prior = o.replay.gps_latency_s;
          if (effect == est::Effect::LeverArm) prior = o.replay.lever_arm_b_m(static_cast<Eigen::Index>(i));
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

}  // namespace sinu::diag
