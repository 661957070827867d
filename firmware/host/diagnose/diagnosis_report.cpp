#include "firmware/host/diagnose/diagnosis_report.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "firmware/host/diagnose/diagnosis_text.hpp"

namespace sinu::diagnose {

namespace {

std::string fmt(const char* f, double v) { return format_number(f, v); }
constexpr const char* kWalkScalesText = "3, 10 and 30";  // diagnose_runner.cpp kWalkScales

}  // namespace

std::string diagnosis_summary(const DiagnoseOptions& o, const Diagnosis& d) {
  std::string out = "diagnose " + o.replay.in_dir + "\n";
  if (d.rounds.empty()) return out;
  const Round& base = d.rounds.front();
  for (const std::string& n : tuned_noise_findings(d)) out += "  noise: " + n + "\n";
  if (const std::string p = process_noise_text(d); !p.empty()) out += "  " + p + "\n";
  out += "  baseline model (" + effect_list(base.model) + "): fits worst in " + worst_cell(base.stats) + "\n";
  if (const std::string h = health_text(base.health); !h.empty()) out += "  baseline solution " + h + "\n";
  if (const std::string f = imu_faults_text(base.health); !f.empty()) out += "  data: " + f + "\n";
  if (d.bias_walk.named) out += "  bias moved: " + bias_walk_text(d.bias_walk) + "\n";
  else if (!d.model_changed() && d.carried.empty()) {
    out += "  no candidate effect explains the misfit (see report.md for each candidate's score)\n";
  }
  for (const Round& round : d.rounds) {
    if (round.found)
      out += std::string(round.candidates.front().changed ? "  changed: " : "  missing effect: ") +
             missing_effect_text(round.candidates.front()) + "\n";
  }
  for (const CarriedFinding& f : d.carried) out += "  carried: " + carried_finding_text(f) + "\n";
  for (const std::string& n : implausible_fits(d, o.min_significance)) out += "  not named: " + n + "\n";
  for (const std::string& n : d.noise_findings) out += "  noise: " + n + "\n";
  if (const std::string u = uncalibrated_text(d); !u.empty()) out += "  caution: " + u + "\n";
  for (const Diagnosis::Skipped& s : d.skipped)
    out += "  not tested: " + std::string(est::spec(s.effect).name) + " (" + s.reason + ")\n";
  const Round& last = d.rounds.back();
  if (d.model_changed()) {
    out += "  error before -> after: " + before_after_text(base, last) + "\n";
    const std::string h = health_text(last.health);
    if (h != health_text(base.health)) out += "  final model's solution " + (h.empty() ? "healthy" : h) + "\n";
  }
  if (!d.model_file.empty())
    out += "  applied: " + d.model_file + " (start the next flight from it: --model-file, or navigation.model_file)\n";
  return out;
}

bool write_diagnosis(const DiagnoseOptions& o, const Diagnosis& d, std::string& error) {
  std::ofstream md(o.out_dir + "/report.md");
  nlohmann::json j;
  j["dataset"] = o.replay.in_dir;
  j["baseline_effects"] = effect_list(o.replay.unit.effects);
  md << "# sinu diagnose: " << o.replay.in_dir << "\n\n";
  md << "Each run is a full `sinu replay` (folders beside this report). NIS per component is y^2/S for each\n"
        "innovation component, averaged: 1 when the filter's model predicts the measurements as well as it\n"
        "claims. A candidate effect is named when adding its states raises the innovations' log-likelihood by\n"
        "more than " << o.min_log_evidence << " (a log Bayes factor: the states start from their prior, so the\n"
        "likelihood already pays for them) and its estimate is at least "
     << o.min_significance << " sigma from zero.\n\n";
  if (!d.rounds.empty()) {
    const Round& base = d.rounds.front();
    md << "## Where the baseline model fails\n\nModel: " << effect_list(base.model) << ". Horizontal RMSE against truth: "
       << rmse_text(base.rmse_pos_h_m, "m") << ", attitude " << rmse_text(base.rmse_att_deg, "deg") << ".\n\n";
    if (const std::string h = health_text(base.health); !h.empty())
      md << "**The baseline's solution was " << h << "**: the misfit broke it.\n\n";
    if (const std::string f = imu_faults_text(base.health); !f.empty()) md << "Data: " << f << ".\n\n";
    md << "| source | components | NIS per component | mean innovation [sigma] | rejected |\n|---|---|---|---|---|\n";
    for (std::size_t k = 0; k < kSources; ++k) {
      const ComponentStats& c = base.stats.source[k];
      if (!c.count) continue;
      md << "| " << kSourceNames[k] << " | " << c.count << " | " << nis_cell(c) << " | " << fmt("%.2f", c.mean_z())
         << " | " << c.rejected << " |\n";
    }
    md << "\nBy flight phase (NIS per component; from the solution's yaw rate, vertical speed and acceleration):\n\n";
    md << "| phase |";
    for (const char* s : kSourceNames) md << " " << s << " |";
    md << "\n|---|---|---|---|\n";
    for (std::size_t p = 0; p < kPhaseCount; ++p) {
      md << "| " << kPhaseNames[p] << " |";
      for (std::size_t k = 0; k < kSources; ++k) md << " " << nis_cell(base.stats.by_phase[k][p]) << " |";
      md << "\n";
    }
    md << "\nWorst fit: " << worst_cell(base.stats) << ".\n\n";
  }
  nlohmann::json rounds = nlohmann::json::array();
  for (std::size_t r = 0; r < d.rounds.size(); ++r) {
    const Round& round = d.rounds[r];
    if (round.candidates.empty()) continue;
    md << "## Round " << r + 1 << ": candidates added to (" << effect_list(round.model) << ")\n\n";
    md << "| effect | log-likelihood gain | threshold | max abs(estimate - assumed)/sigma | estimate | NIS pos / vel / mag | "
          "horizontal RMSE vs truth |\n|---|---|---|---|---|---|---|\n";
    nlohmann::json cands = nlohmann::json::array();
    for (const CandidateResult& c : round.candidates) {
      const auto e = static_cast<std::size_t>(c.effect);
      md << "| " << candidate_name(c) << (c.explains(o.min_significance) ? " **(explains)**" : "")
         << (c.implausible_fit(o.min_significance) ? " (fits, but implausibly large)" : "") << " | "
         << fmt("%.1f", c.nll_gain) << " | " << fmt("%.1f", c.evidence_threshold) << " | " << fmt("%.1f", c.significance)
         << " | " << estimate_text(c) << " | " << nis_cell(c.stats.source[0]) << " / " << nis_cell(c.stats.source[1])
         << " / " << nis_cell(c.stats.source[2]) << " | " << rmse_text(c.rmse_pos_h_m, "m") << " |\n";
      cands.push_back({{"effect", est::kEffectNames[e]}, {"nll_gain", c.nll_gain}, {"evidence_threshold", c.evidence_threshold},
                       {"significance", c.significance}, {"estimate", c.estimate}, {"sigma", c.sigma}, {"held", c.held},
                       {"explains", c.explains(o.min_significance)}, {"plausibility", c.plausibility},
                       {"rmse_pos_h_m", c.rmse_pos_h_m}, {"changed_since_model_file", c.changed}});
    }
    md << "\n";
    rounds.push_back({{"model", effect_list(round.model)}, {"found", round.found}, {"candidates", cands}});
  }
  j["rounds"] = rounds;
  auto names = [](const std::vector<est::Effect>& effects) {
    nlohmann::json out = nlohmann::json::array();
    for (est::Effect e : effects) out.push_back(est::kEffectNames[static_cast<std::size_t>(e)]);
    return out;
  };
  j["missing_effects"] = names(d.missing);
  j["changed_effects"] = names(d.changed);
  nlohmann::json carried_json = nlohmann::json::array();
  if (!d.carried.empty()) {
    md << "## Carried, and far from what was assumed\n\n"
          "The model carries these effects as states from an assumed value (the configured latency and lever\n"
          "arm, a hard iron of zero): they followed the data, so nothing is missing, but the unit has them.\n\n";
    for (const CarriedFinding& f : d.carried) {
      md << "- " << carried_finding_text(f) << "\n";
      carried_json.push_back({{"effect", est::spec(f.effect).name}, {"assumed", f.assumed},
                              {"estimate", f.estimate}, {"sigma", f.sigma}, {"significance", f.significance}});
    }
    md << "\n";
  }
  j["carried_findings"] = carried_json;
  nlohmann::json skipped = nlohmann::json::array();
  if (!d.skipped.empty()) {
    md << "## Not tested: the data cannot tell\n\n";
    for (const Diagnosis::Skipped& s : d.skipped) {
      md << "- `" << est::spec(s.effect).name << "`: " << s.reason << "\n";
      skipped.push_back({{"effect", est::spec(s.effect).name}, {"reason", s.reason}});
    }
    md << "\n";
  }
  j["skipped"] = skipped;
  if (!d.observability.empty()) {
    md << "## Weakly observable in this flight\n\n";
    for (const std::string& n : d.observability) md << "- " << n << "\n";
    md << "\n";
  }
  j["weakly_observable"] = d.observability;
  j["noise_findings"] = d.noise_findings;
  j["calibrated"] = d.calibrated;
  if (const std::string u = uncalibrated_text(d); !u.empty()) j["caution"] = u;
  if (d.bias_walk.tested) {
    md << "## Did a bias move?\n\nThe baseline replayed with each sensor's bias random walk " << kWalkScalesText
       << " times calib.json's: " << bias_walk_text(d.bias_walk) << ".\n\n";
    j["bias_walk"] = {{"sensor", d.bias_walk.gyro ? "gyro" : "accel"}, {"scale", d.bias_walk.scale},
                      {"nll_gain", d.bias_walk.nll_gain},  {"threshold", d.bias_walk.threshold},
                      {"best_effect_gain", d.bias_walk.best_effect_gain}, {"named", d.bias_walk.named}};
  }
  md << "## Conclusion\n\n```\n" << diagnosis_summary(o, d) << "```\n";
  if (!d.model_changed() && d.carried.empty()) {
    md << "\nNo effect the EKF can estimate explains the misfit. What the vocabulary does not cover: a\n"
          "magnetometer misfit beyond soft iron and a misalignment (a field that moves with the motors, a\n"
          "magnetometer sampled late), vibration rectification, a receiver whose error changes with the\n"
          "satellites in view.\n";
  }
  if (!d.rounds.empty()) {
    auto whiteness = [](const Round& r) {
      nlohmann::json w = nlohmann::json::object();
      for (std::size_t k = 0; k < kSources; ++k)
        if (r.stats.source[k].count) w[kSourceNames[k]] = r.stats.source[k].lag1();
      return w;
    };
    // What the IMU did not measure (the baseline's replay; every candidate's reads the same data).
    const est::NavCounters& c = d.rounds.front().health.counters;
    j["imu_faults"] = {{"clipped_samples", c.imu_clipped_samples}, {"gaps", c.imu_gaps},
                       {"longest_gap_s", c.imu_longest_gap_s}, {"dropped_nan", c.imu_invalid},
                       {"dropped_time", c.imu_non_increasing}};
    j["before"] = {{"rmse_pos_h_m", d.rounds.front().rmse_pos_h_m},
                   {"rmse_att_deg", d.rounds.front().rmse_att_deg},
                   {"nll", d.rounds.front().stats.total_nll()},
                   {"outage_drift_h_m", d.rounds.front().outage_drift_h_m}, {"lag1", whiteness(d.rounds.front())}};
    j["after"] = {{"rmse_pos_h_m", d.rounds.back().rmse_pos_h_m},
                  {"rmse_att_deg", d.rounds.back().rmse_att_deg},
                  {"nll", d.rounds.back().stats.total_nll()},
                  {"outage_drift_h_m", d.rounds.back().outage_drift_h_m}, {"lag1", whiteness(d.rounds.back())},
                  {"effects", effect_list(d.rounds.back().model)}};
  }
  std::ofstream js(o.out_dir + "/diagnosis.json");
  js << j.dump(2) << "\n";
  if (!md || !js) {
    error = o.out_dir + ": writing report.md / diagnosis.json failed";
    return false;
  }
  return true;
}

}  // namespace sinu::diagnose
