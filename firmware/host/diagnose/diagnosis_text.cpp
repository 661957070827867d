#include "firmware/host/diagnose/diagnosis_text.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "firmware/host/diagnose/configured_effects.hpp"

namespace sinu::diagnose {

namespace {

// The model's error in one run: RMSE against truth and NIS per source.
/// ", outage drift X m" when --outage windows were scored, else "".
std::string drift_text(const Round& r) {
  return r.outage_drift_h_m >= 0.0 ? ", outage drift " + rmse_text(r.outage_drift_h_m, "m") : "";
}

std::string error_text(const Round& r) {
  std::string out = "horizontal RMSE " + rmse_text(r.rmse_pos_h_m, "m") + ", attitude " + rmse_text(r.rmse_att_deg, "deg") +
                    drift_text(r) + "; NIS per component";
  for (std::size_t k = 0; k < kSources; ++k) {
    if (r.stats.source[k].count) out += std::string(" ") + kSourceNames[k] + " " + nis_cell(r.stats.source[k]);
  }
  return out;
}

}  // namespace

std::string format_number(const char* printf_format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, printf_format, v);
  return buf;
}

std::string effect_list(const est::EffectSet& s) {
  std::string out;
  for (std::size_t e = 0; e < est::kEffectCount; ++e) {
    if (!s.has(static_cast<est::Effect>(e))) continue;
    if (!out.empty()) out += ", ";
    out += est::kEffectNames[e];
  }
  return out.empty() ? "none" : out;
}

namespace {

std::string value_text(est::Effect e, double value, double sigma, const char* plus_minus) {
  const double scale = est::spec(e).display_scale;
  return format_number("%.4g", value * scale) + " " + plus_minus + " " + format_number("%.2g", sigma * scale);
}

std::string vector_text(est::Effect e, const std::vector<double>& value, const std::vector<double>& sigma,
                        const std::vector<bool>& held = {}) {
  std::string out;
  for (std::size_t i = 0; i < value.size() && i < sigma.size(); ++i) {
    if (i) out += ", ";
    out += i < held.size() && held[i] ? std::string("held") : value_text(e, value[i], sigma[i], "+-");
  }
  if (value.size() > 1) out = "[" + out + "]";
  return out + " " + est::spec(e).unit;
}

}  // namespace

std::string estimate_component_text(const CandidateResult& c, std::size_t i, const char* plus_minus) {
  if (i < c.held.size() && c.held[i]) return "held";
  return value_text(c.effect, c.estimate[i], c.sigma[i], plus_minus);
}

std::string estimate_text(const CandidateResult& c) { return vector_text(c.effect, c.estimate, c.sigma, c.held); }

std::string candidate_name(const CandidateResult& c) {
  return std::string(est::spec(c.effect).name) + (c.changed ? " (re-learnt)" : "");
}

std::string nis_cell(const ComponentStats& s) { return s.count ? format_number("%.2f", s.nis()) : std::string("-"); }

std::string rmse_text(double v, const char* unit) {
  return v >= 0.0 ? format_number("%.3g", v) + " " + unit : std::string("n/a");
}

// A missing effect shows up where the vehicle does what excites it (a latency
// in speed changes, a lever arm in turns): the phase whose NIS stands out most
// from the same source's flight average.
std::size_t worst_phase(const InnovationStats& s, std::size_t k, double& ratio) {
  ratio = 0.0;
  std::size_t worst = kPhaseCount;
  const double overall = s.source[k].nis();
  if (!(overall > 0.0)) return worst;
  for (std::size_t p = 0; p < kPhaseCount; ++p) {
    const ComponentStats& c = s.by_phase[k][p];
    if (c.count < 50 || c.nis() / overall <= ratio) continue;
    ratio = c.nis() / overall;
    worst = p;
  }
  return worst;
}

std::string worst_cell(const InnovationStats& s) {
  double worst = 0.0;
  std::string text;
  for (std::size_t k = 0; k < kSources; ++k) {
    double ratio = 0.0;
    const std::size_t p = worst_phase(s, k, ratio);
    if (p == kPhaseCount || ratio <= worst) continue;
    worst = ratio;
    text = std::string(kSourceNames[k]) + " during " + kPhaseNames[p] + " (NIS " +
           format_number("%.2f", s.by_phase[k][p].nis()) + ", " + format_number("%.1f", ratio) +
           "x its flight average " + format_number("%.2f", s.source[k].nis()) + "; 1 when the model is right)";
  }
  return text;
}

std::vector<std::string> tuned_noise_findings(const Diagnosis& d) {
  // A noise level is a diagnosis too: which sigma, how far off, and why it is noise.
  // f = the sigma used / the sigma given: "2.03x too small (NIS per component 4.11"
  auto off_by = [](double f) {
    return format_number("%.2f", f > 1.0 ? f : 1.0 / f) + "x too " + (f > 1.0 ? "small" : "large") +
           " (NIS per component " + format_number("%.2f", f * f);
  };
  auto tuned_line = [&](const char* what, double given, double used, const char* unit) {
    const double f = used / given;
    std::string line = std::string(what) + " sigma " + format_number("%.3g", given) + " " + unit + " was set " + off_by(f);
    if (f > 1.0) line += ", alike in every flight phase: a noise level, not a missing effect";
    line += "); diagnosed with " + format_number("%.3g", used) + " " + unit;
    return line;
  };
  std::vector<std::string> out;
  if (d.mag_sigma_uT != d.mag_sigma_given_uT)
    out.push_back(tuned_line("magnetometer", d.mag_sigma_given_uT, d.mag_sigma_uT, "uT"));
  if (d.vel_sigma_m_s != d.vel_sigma_given_m_s)
    out.push_back(tuned_line("GNSS velocity", d.vel_sigma_given_m_s, d.vel_sigma_m_s, "m/s"));
  if (d.pos_sigma_scale != d.pos_sigma_scale_given) {
    out.push_back("GNSS position sigma (the receiver's GST, or HDOP x UERE) is " +
                  off_by(d.pos_sigma_scale / d.pos_sigma_scale_given) + "); diagnosed with --gps-pos-sigma-scale " +
                  format_number("%.3g", d.pos_sigma_scale));
  }
  return out;
}

std::string process_noise_text(const Diagnosis& d) {
  if (d.process_noise_scale == 1.0) return "";
  return "no calib.json: the built-in sensor model's coloured-error variances scaled by " +
         format_number("%.2g", d.process_noise_scale) + " (maximum likelihood of the innovations)";
}

std::string uncalibrated_text(const Diagnosis& d) {
  // A simulated unit's 0.04-deg/s gyro oscillation (12-s period, which its
  // bench session's AR model carries) was named a 3 % gyro y scale without it.
  if (d.calibrated || !d.model_changed()) return "";
  return "without --calib the IMU's noise is the built-in model's, not this unit's: an effect named here may "
         "stand for noise that model lacks; a bench session of the unit (sinu calibrate) tells them apart";
}

std::string missing_effect_text(const CandidateResult& c) {
  const std::string value = c.changed ? " has changed since the model file: " + estimate_text(c) + ", was " +
                                            vector_text(c.effect, c.file_estimate, c.file_sigma)
                                      : " = " + estimate_text(c);
  return std::string(est::spec(c.effect).name) + value + " (innovation log-likelihood +" +
         format_number("%.1f", c.nll_gain) + ", threshold " + format_number("%.1f", c.evidence_threshold) + ")";
}

std::string carried_finding_text(const CarriedFinding& f) {
  const est::EffectSpec& sp = est::spec(f.effect);
  std::string assumed, option;
  for (std::size_t k = 0; k < f.assumed.size(); ++k) {
    assumed += fmt::format("{}{:.4g}", k ? ", " : "", f.assumed[k] * sp.display_scale);
    option += fmt::format("{}{:.3g}", k ? "," : "", f.estimate[k]);
  }
  if (f.assumed.size() > 1) assumed = "[" + assumed + "]";
  // What to do: the option that configures it, or the model file alone.
  const ConfiguredEffect* configured = configured_effect(f.effect);
  std::string advice = configured ? fmt::format("the configuration is wrong: {} {} or --apply", configured->option, option)
                                  : "a property of this unit or airframe; --apply writes it, so the next flight "
                                    "starts from it";
  if (f.imu_latency_s() > 0.0) {
    advice = fmt::format("below zero the fixes are valid after they arrive on the IMU's clock: the IMU's samples are "
                         "stamped late, by {:.3f} s if the receiver's latency is the assumed {:.3g} s; --imu-latency "
                         "{:.3f} or --apply",
                         f.imu_latency_s(), f.assumed[0], f.imu_latency_s());
  }
  return fmt::format("{} = {}, assumed {} {} ({:.0f} sigma, {} {} off; the model carries it and its states followed "
                     "it: {})",
                     sp.name, vector_text(f.effect, f.estimate, f.sigma), assumed, sp.unit, f.significance,
                     format_number("%.3g", f.deviation * sp.display_scale), sp.unit, advice);
}

std::string implausible_fit_text(const CandidateResult& c) {
  const est::EffectSpec& sp = est::spec(c.effect);
  return std::string(sp.name) + " would fit (log-likelihood +" + format_number("%.1f", c.nll_gain) + ") but only at " +
         format_number("%.3g", c.plausibility * sp.plausible_max * sp.display_scale) + " " + sp.unit + ", beyond the " +
         format_number("%.3g", sp.plausible_max * sp.display_scale) + " " + sp.unit +
         " a real unit has: the misfit is something else";
}

std::vector<std::string> implausible_fits(const Diagnosis& d, double min_significance) {
  std::vector<std::string> out;
  est::EffectSet told;  // an effect named in a later round (beside the one that fit first) is no such misfit
  for (const est::Effect e : d.missing) told.add(e);
  for (const est::Effect e : d.changed) told.add(e);
  for (const Round& round : d.rounds) {
    for (const CandidateResult& c : round.candidates) {
      if (!c.implausible_fit(min_significance) || told.has(c.effect)) continue;
      told.add(c.effect);
      out.push_back(implausible_fit_text(c));
    }
  }
  return out;
}

std::string bias_walk_text(const BiasWalkFinding& w) {
  if (!w.tested) return "";
  const char* sensor = w.gyro ? "gyro" : "accelerometer";
  if (!w.named)
    return fmt::format("the calibrated bias walks fit: the best, the {}'s {:g}x, changes the innovations' "
                       "log-likelihood by {:+.1f} (threshold {:.1f})",
                       sensor, w.scale, w.nll_gain, w.threshold);
  return fmt::format("the {} bias moved more than calib.json's random walk allows: {:g}x its walk raises the "
                     "innovations' log-likelihood by +{:.1f} (threshold {:.1f}, the best effect +{:.1f}). A bias "
                     "that shifted in flight (a shock, a temperature step) or another unit than the one calibrated; "
                     "no effect is named for it. Replay with --{}-bias-walk-scale {:g} to follow it",
                     sensor, w.scale, w.nll_gain, w.threshold, w.best_effect_gain, w.gyro ? "gyro" : "accel", w.scale);
}

std::string health_text(const SolutionHealth& h) {
  switch (h.status) {
    case replay::HealthStatus::Ok: return "";
    case replay::HealthStatus::Reset: return "reset to GNSS " + std::to_string(h.counters.resets()) + " time(s)";
    case replay::HealthStatus::LostAndRecovered:
      return "lost for " + format_number("%.1f", h.counters.lost_total_s) + " s, recovered by " +
             std::to_string(h.counters.resets()) +
             " reset(s)";
    case replay::HealthStatus::Lost:
      return "LOST at the end of the data (" + format_number("%.1f", h.counters.lost_total_s) + " s)";
    case replay::HealthStatus::NotAligned: return "never aligned";
  }
  return "";
}

std::string imu_faults_text(const SolutionHealth& h) {
  const est::NavCounters& c = h.counters;
  const std::uint64_t dropped = c.imu_invalid + c.imu_non_increasing;
  if (c.imu_clipped_samples == 0 && c.imu_gaps == 0 && dropped == 0) return "";
  std::string parts;
  const auto add = [&parts](const std::string& p) { parts += (parts.empty() ? "" : ", ") + p; };
  if (c.imu_clipped_samples > 0) add(std::to_string(c.imu_clipped_samples) + " sample(s) at full scale");
  if (c.imu_gaps > 0)
    add(std::to_string(c.imu_gaps) + " gap(s) (longest " + format_number("%.3g", c.imu_longest_gap_s) + " s)");
  if (dropped > 0)
    add(std::to_string(dropped) + " sample(s) dropped (NaN " + std::to_string(c.imu_invalid) + ", time " +
        std::to_string(c.imu_non_increasing) + ")");
  return "the IMU has " + parts +
         ": there it did not measure the motion, the filter widened its noise over it, and a misfit there is no "
         "effect of the unit (a unit that clips wants a wider full scale: the ICM-20948 has +-16 g, +-2000 deg/s)";
}

std::string before_after_text(const Round& before, const Round& after) {
  std::string out = "horizontal RMSE " + rmse_text(before.rmse_pos_h_m, "m") + " -> " +
                    rmse_text(after.rmse_pos_h_m, "m") + ", attitude " + rmse_text(before.rmse_att_deg, "deg") + " -> " +
                    rmse_text(after.rmse_att_deg, "deg");
  if (before.outage_drift_h_m >= 0.0)
    out += ", outage drift " + rmse_text(before.outage_drift_h_m, "m") + " -> " + rmse_text(after.outage_drift_h_m, "m");
  out += "; NIS per component";
  for (std::size_t k = 0; k < kSources; ++k) {
    if (!before.stats.source[k].count) continue;
    out += std::string(" ") + kSourceNames[k] + " " + nis_cell(before.stats.source[k]) + " -> " +
           nis_cell(after.stats.source[k]);
  }
  out += "; innovation whiteness (lag-1 autocorrelation, 0 when white)";
  for (std::size_t k = 0; k < kSources; ++k) {
    if (!before.stats.source[k].count) continue;
    out += std::string(" ") + kSourceNames[k] + " " + format_number("%.2f", before.stats.source[k].lag1()) + " -> " +
           format_number("%.2f", after.stats.source[k].lag1());
  }
  return out;
}

std::string conclusion_sentence(const Diagnosis& d) {
  if (d.rounds.empty()) return "No diagnosis: the baseline replay did not run.";
  std::string found;
  for (const Round& round : d.rounds) {
    if (!round.found) continue;
    if (!found.empty()) found += "; ";
    found += missing_effect_text(round.candidates.front());
  }
  if (d.bias_walk.named) {
    return fmt::format("The {} bias moved during the flight, more than its calibrated walk allows (no effect of the "
                       "vocabulary explains it as well){}. Error before -> after, its walk {:g}x{}: {}.",
                       d.bias_walk.gyro ? "gyro" : "accelerometer", found.empty() ? "" : "; with its walk widened, " + found,
                       d.bias_walk.scale, found.empty() ? "" : " and the effects", before_after_text(d.rounds.front(), d.rounds.back()));
  }
  std::string carried;
  for (const CarriedFinding& f : d.carried)
    carried += (carried.empty() ? " Carried, and far from what was assumed: " : "; ") + carried_finding_text(f);
  if (!carried.empty()) carried += ".";
  if (!found.empty()) {
    const char* what = d.missing.empty() ? "Changed: " : d.missing.size() > 1 ? "Missing effects: " : "Missing effect: ";
    return what + found +
           ". Error before -> after: " + before_after_text(d.rounds.front(), d.rounds.back()) + "." + carried;
  }
  if (!carried.empty()) return carried.substr(1);
  const std::string error = error_text(d.rounds.back());
  if (d.noise_findings.empty())
    return "The model explains the data: no candidate effect raises the innovations' log-likelihood beyond the "
           "threshold. Error: " + error + ".";
  return "No effect of the vocabulary explains the misfit, and " + std::to_string(d.noise_findings.size()) +
         " noise level" + (d.noise_findings.size() > 1 ? "s do" : " does") + " not fit (see the noise findings). Error: " +
         error + ".";
}

}  // namespace sinu::diagnose
