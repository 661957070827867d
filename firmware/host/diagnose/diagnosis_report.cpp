#include "firmware/host/diagnose/diagnosis_report.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

namespace sinu::diagnose {

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string effect_list(const est::EffectSet& s) {
  std::string out;
  for (std::size_t e = 0; e < est::kEffectCount; ++e) {
    if (s.has(static_cast<est::Effect>(e))) out += std::string(out.empty() ? "" : ", ") + est::kEffectNames[e];
  }
  return out.empty() ? "none" : out;
}

std::string estimate_text(const CandidateResult& c) {
  const auto e = static_cast<std::size_t>(c.effect);
  std::string out;
  for (std::size_t i = 0; i < c.estimate.size(); ++i) {
    out += (i ? ", " : "") + fmt("%.4g", c.estimate[i] * est::kEffects[e].display_scale) + " +- " +
           fmt("%.2g", c.sigma[i] * est::kEffects[e].display_scale);
  }
  return (c.estimate.size() > 1 ? "[" + out + "]" : out) + " " + est::kEffects[e].unit;
}

std::string nis_cell(const ComponentStats& s) { return s.count ? fmt("%.2f", s.nis()) : std::string("-"); }

std::string rmse_text(double v, const char* unit) { return v >= 0.0 ? fmt("%.3g", v) + " " + unit : std::string("n/a"); }

// The (source, phase) cell where the model fits worst relative to the same
// source over the whole flight: a missing effect shows up where the vehicle
// does what excites it (a latency in speed changes, a lever arm in turns).
std::string worst_cell(const InnovationStats& s) {
  double worst = 0.0;
  std::string text;
  for (std::size_t k = 0; k < kSources; ++k) {
    const double overall = s.source[k].nis();
    if (!(overall > 0.0)) continue;
    for (std::size_t p = 0; p < kPhaseCount; ++p) {
      const ComponentStats& c = s.by_phase[k][p];
      if (c.count < 50 || c.nis() / overall <= worst) continue;
      worst = c.nis() / overall;
      text = std::string(kSourceNames[k]) + " during " + kPhaseNames[p] + " (NIS " + fmt("%.2f", c.nis()) + ", " +
             fmt("%.1f", worst) + "x its flight average " + fmt("%.2f", overall) + "; 1 when the model is right)";
    }
  }
  return text;
}

}  // namespace

std::string diagnosis_summary(const DiagnoseOptions& o, const Diagnosis& d) {
  std::string out = "diagnose " + o.replay.in_dir + "\n";
  if (d.rounds.empty()) return out;
  const Round& base = d.rounds.front();
  // A noise level is a diagnosis too: which sigma, how far off, and why it is noise.
  auto tuned_line = [&](const char* what, double given, double used, const char* unit) {
    const double f = used / given;
    return std::string("  noise: ") + what + " sigma " + fmt("%.3g", given) + " " + unit + " was set " +
           fmt("%.2f", f > 1.0 ? f : 1.0 / f) + "x too " + (f > 1.0 ? "small" : "large") + " (NIS per component " +
           fmt("%.2f", f * f) + (f > 1.0 ? ", alike in every flight phase: a noise level, not a missing effect" : "") +
           "); diagnosed with " + fmt("%.3g", used) + " " + unit + "\n";
  };
  if (d.mag_sigma_uT != d.mag_sigma_given_uT) out += tuned_line("magnetometer", d.mag_sigma_given_uT, d.mag_sigma_uT, "uT");
  if (d.vel_sigma_m_s != d.vel_sigma_given_m_s)
    out += tuned_line("GNSS velocity", d.vel_sigma_given_m_s, d.vel_sigma_m_s, "m/s");
  if (d.process_noise_scale != 1.0) {
    out += "  no calib.json: the built-in sensor model's coloured-error variances scaled by " +
           fmt("%.2g", d.process_noise_scale) + " (maximum likelihood of the innovations)\n";
  }
  out += "  baseline model (" + effect_list(base.model) + "): fits worst in " + worst_cell(base.stats) + "\n";
  if (d.missing.empty()) {
    out += "  no candidate effect explains the misfit (see report.md for each candidate's score)\n";
  }
  for (std::size_t r = 0; r < d.rounds.size(); ++r) {
    const Round& round = d.rounds[r];
    if (!round.found) continue;
    const CandidateResult& c = round.candidates.front();
    out += "  missing effect: " + std::string(est::kEffectNames[static_cast<std::size_t>(c.effect)]) + " = " +
           estimate_text(c) + " (innovation log-likelihood +" + fmt("%.1f", c.nll_gain) + ", BIC penalty " +
           fmt("%.1f", c.penalty) + ")\n";
  }
  est::EffectSet told;  // each implausible fit once (the first round it appeared in)
  for (const Round& round : d.rounds) {
    for (const CandidateResult& c : round.candidates) {
      if (!c.implausible_fit(o.min_significance) || told.has(c.effect)) continue;
      told.add(c.effect);
      const est::EffectSpec& sp = est::spec(c.effect);
      out += "  not named: " + std::string(sp.name) + " would fit (log-likelihood +" + fmt("%.1f", c.nll_gain) +
             ") but only at " + fmt("%.3g", c.plausibility * sp.plausible_max * sp.display_scale) + " " + sp.unit +
             ", beyond the " + fmt("%.3g", sp.plausible_max * sp.display_scale) + " " + sp.unit +
             " a real unit has: the misfit is something else\n";
    }
  }
  for (const std::string& n : d.noise_findings) out += "  noise: " + n + "\n";
  for (const Diagnosis::Skipped& s : d.skipped)
    out += "  not tested: " + std::string(est::spec(s.effect).name) + " (" + s.reason + ")\n";
  const Round& last = d.rounds.back();
  if (!d.missing.empty()) {
    out += "  error before -> after: horizontal RMSE " + rmse_text(base.rmse_pos_h_m, "m") + " -> " +
           rmse_text(last.rmse_pos_h_m, "m") + ", attitude " + rmse_text(base.rmse_att_deg, "deg") + " -> " +
           rmse_text(last.rmse_att_deg, "deg") + "; NIS per component";
    for (std::size_t k = 0; k < kSources; ++k) {
      if (!base.stats.source[k].count) continue;
      out += std::string(" ") + kSourceNames[k] + " " + nis_cell(base.stats.source[k]) + " -> " +
             nis_cell(last.stats.source[k]);
    }
    out += "\n";
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
        "more than the BIC penalty 0.5 k ln(N) and its estimate is at least "
     << o.min_significance << " sigma from zero.\n\n";
  if (!d.rounds.empty()) {
    const Round& base = d.rounds.front();
    md << "## Where the baseline model fails\n\nModel: " << effect_list(base.model) << ". Horizontal RMSE against truth: "
       << rmse_text(base.rmse_pos_h_m, "m") << ", attitude " << rmse_text(base.rmse_att_deg, "deg") << ".\n\n";
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
    md << "| effect | log-likelihood gain | BIC penalty | max abs(estimate - assumed)/sigma | estimate | NIS pos / vel / mag | "
          "horizontal RMSE vs truth |\n|---|---|---|---|---|---|---|\n";
    nlohmann::json cands = nlohmann::json::array();
    for (const CandidateResult& c : round.candidates) {
      const auto e = static_cast<std::size_t>(c.effect);
      md << "| " << est::kEffectNames[e] << (c.explains(o.min_significance) ? " **(explains)**" : "")
         << (c.implausible_fit(o.min_significance) ? " (fits, but implausibly large)" : "") << " | "
         << fmt("%.1f", c.nll_gain) << " | " << fmt("%.1f", c.penalty) << " | " << fmt("%.1f", c.significance)
         << " | " << estimate_text(c) << " | " << nis_cell(c.stats.source[0]) << " / " << nis_cell(c.stats.source[1])
         << " / " << nis_cell(c.stats.source[2]) << " | " << rmse_text(c.rmse_pos_h_m, "m") << " |\n";
      cands.push_back({{"effect", est::kEffectNames[e]}, {"nll_gain", c.nll_gain}, {"penalty", c.penalty},
                       {"significance", c.significance}, {"estimate", c.estimate}, {"sigma", c.sigma},
                       {"explains", c.explains(o.min_significance)}, {"plausibility", c.plausibility},
                       {"rmse_pos_h_m", c.rmse_pos_h_m}});
    }
    md << "\n";
    rounds.push_back({{"model", effect_list(round.model)}, {"found", round.found}, {"candidates", cands}});
  }
  j["rounds"] = rounds;
  nlohmann::json missing = nlohmann::json::array();
  for (est::Effect e : d.missing) missing.push_back(est::kEffectNames[static_cast<std::size_t>(e)]);
  j["missing_effects"] = missing;
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
  md << "## Conclusion\n\n```\n" << diagnosis_summary(o, d) << "```\n";
  if (d.missing.empty()) {
    md << "\nNo effect the EKF can estimate explains the misfit. What the vocabulary does not cover: a\n"
          "magnetometer misfit that changes with heading beyond soft iron (a field that moves with the motors),\n"
          "vibration rectification, a receiver whose error changes with the satellites in view.\n";
  }
  if (!d.rounds.empty()) {
    j["before"] = {{"rmse_pos_h_m", d.rounds.front().rmse_pos_h_m}, {"nll", d.rounds.front().stats.total_nll()}};
    j["after"] = {{"rmse_pos_h_m", d.rounds.back().rmse_pos_h_m}, {"nll", d.rounds.back().stats.total_nll()},
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
