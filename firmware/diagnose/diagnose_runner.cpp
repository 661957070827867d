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
  if (!replay_and_score(o.replay, model, (fs::path(o.replay.out_dir) / "baseline").string(), current, error)) return false;
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
      if (!replay_and_score(o.replay, trial, dir, score, error)) return false;
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
  return write_diagnosis(o, out, error);
}

}  // namespace sinu::diag
