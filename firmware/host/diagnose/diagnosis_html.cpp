#include "firmware/host/diagnose/diagnosis_html.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>

#include "firmware/host/dataset/quantile.hpp"
#include "firmware/host/diagnose/diagnosis_text.hpp"
#include "firmware/host/diagnose/svg_plot.hpp"

namespace sinu::diagnose {

namespace {

using svg::escape;

// Time plots: min/max pairs across the plot (about twice its pixel columns:
// zoomed in 2x it still shows each column's extremes), fewer columns for the
// slowly varying sigma, the flight phase as the majority per column.
constexpr int kInnovationColumns = 2000;
constexpr int kSigmaColumns = 500;
constexpr int kPhaseColumns = 1000;
// A phase whose NIS is this many times the source's flight average is shaded over the whole plot.
constexpr double kStandsOut = 1.25;

// One colour per flight phase (Okabe-Ito, readable with colour blindness):
// the shading, the bars and the legend.
constexpr std::array<const char*, kPhaseCount> kPhaseColours = {"#a0a0a0", "#e69f00", "#56b4e9", "#009e73", "#cc79a7"};

std::string phase_class(std::size_t p) { return "p" + std::to_string(p); }

std::string tag(const char* name, const std::string& text, const std::string& css_class = "") {
  std::string out = std::string("<") + name;
  if (!css_class.empty()) out += " class=\"" + css_class + "\"";
  return out + ">" + text + "</" + name + ">";
}

std::string list_items(const std::vector<std::string>& items) {
  std::string out = "<ul>";
  for (const std::string& i : items) out += tag("li", escape(i));
  return out + "</ul>\n";
}

// NIS per component: near 1 when the model is right.
std::string nis_class(const ComponentStats& s) {
  if (!s.count) return "";
  const double nis = s.nis();
  if (nis < 0.7) return "low";
  if (nis <= 1.3) return "ok";
  return nis <= 3.0 ? "high" : "vhigh";
}

// ---- the flight phases, shaded under every time plot ----------------------

// Seconds each column of the flight spent in each phase.
std::vector<std::array<double, kPhaseCount>> phase_time_per_column(const InnovationSeries& s, double span_s) {
  std::vector<std::array<double, kPhaseCount>> out(kPhaseColumns, std::array<double, kPhaseCount>{});
  const double column_s = span_s / kPhaseColumns;
  for (const PhaseSpan& p : s.phases) {
    double a = p.start_s - s.t_first_s;
    const double b = p.end_s - s.t_first_s;
    while (a < b) {
      const int col = std::min(kPhaseColumns - 1, static_cast<int>(a / column_s));
      const double end = col == kPhaseColumns - 1 ? b : std::min(b, (col + 1) * column_s);
      out[static_cast<std::size_t>(col)][static_cast<std::size_t>(p.phase)] += end - a;
      a = std::max(end, std::nextafter(a, b));
    }
  }
  return out;
}

// One group of rectangles per phase (seconds after the first solution, 0..1
// high), in a hidden <svg>: each plot shows them with <use>, so they are written once.
std::string phase_defs(const InnovationSeries& s, double span_s) {
  const auto time = phase_time_per_column(s, span_s);
  const double column_s = span_s / kPhaseColumns;
  std::array<std::string, kPhaseCount> rects;
  std::size_t run_phase = kPhaseCount;
  int run_start = 0;
  auto close_run = [&](int end) {
    if (run_phase == kPhaseCount) return;
    rects[run_phase] += "<rect x=\"" + svg::number(run_start * column_s, 7) + "\" y=\"0\" width=\"" +
                        svg::number((end - run_start) * column_s, 7) + "\" height=\"1\"/>";
  };
  for (int c = 0; c < kPhaseColumns; ++c) {
    const auto& t = time[static_cast<std::size_t>(c)];
    const auto best = static_cast<std::size_t>(std::max_element(t.begin(), t.end()) - t.begin());
    const std::size_t phase = t[best] > 0.0 ? best : kPhaseCount;
    if (phase == run_phase) continue;
    close_run(c);
    run_phase = phase;
    run_start = c;
  }
  close_run(kPhaseColumns);
  std::string out = "<svg class=\"defs\" width=\"0\" height=\"0\" aria-hidden=\"true\"><defs>";
  for (std::size_t p = 0; p < kPhaseCount; ++p)
    out += "<g id=\"phase-" + std::to_string(p) + "\" fill=\"" + kPhaseColours[p] + "\">" + rects[p] + "</g>";
  return out + "</defs></svg>\n";
}

// Every phase as a strip along the top of the plot; the source's worst phase
// (when it stands out) also over the whole height.
std::string phase_shading(std::size_t worst) {
  std::string out;
  if (worst < kPhaseCount) out += "<use href=\"#phase-" + std::to_string(worst) + "\" class=\"ph worst\"/>";
  for (std::size_t p = 0; p < kPhaseCount; ++p)
    out += "<use href=\"#phase-" + std::to_string(p) + "\" class=\"ph strip\" transform=\"scale(1 0.06)\"/>";
  return out;
}

std::string phase_legend() {
  std::string out;
  for (std::size_t p = 0; p < kPhaseCount; ++p)
    out += "<span><i class=\"sw " + phase_class(p) + "\"></i>" + escape(kPhaseNames[p]) + "</span>";
  return out;
}

// ---- the innovations over time --------------------------------------------

// The value range of a plot: the innovations up to their 99.5th percentile (a
// few outliers drawn at the edge) and at least 3.5 sigma.
double value_range(const std::vector<svg::Sample>& innovation, const std::vector<svg::Sample>& sigma) {
  std::vector<double> size, s;
  for (const svg::Sample& x : innovation) size.push_back(std::abs(x.y));
  for (const svg::Sample& x : sigma) s.push_back(x.y);
  const double r = std::max(dataset::quantile(size, 0.995), 3.5 * dataset::quantile(s, 0.5));
  return r > 0.0 ? 1.1 * r : 1.0;
}

// A break in the line: five typical intervals without a measurement (an outage), at least two columns.
double gap_threshold_s(const std::vector<svg::Sample>& samples, double span_s) {
  std::vector<double> dt;
  for (std::size_t i = 1; i < samples.size(); ++i) dt.push_back(samples[i].t_s - samples[i - 1].t_s);
  return std::max(5.0 * dataset::quantile(dt, 0.5), 2.0 * span_s / kInnovationColumns);
}

struct ComponentSeries {
  std::vector<svg::Sample> innovation, sigma, rejected;
  ComponentStats stats;
};

ComponentSeries component_series(std::vector<InnovationPoint> points) {
  std::stable_sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.t_s < b.t_s; });
  ComponentSeries out;
  for (const InnovationPoint& p : points) {
    out.innovation.push_back({p.t_s, p.innovation});
    out.sigma.push_back({p.t_s, p.sigma});
    if (!p.accepted) out.rejected.push_back({p.t_s, p.innovation});
    out.stats.add(p.innovation, p.sigma, p.accepted);
  }
  return out;
}

std::string component_plot(const InnovationSeries& s, std::size_t source, std::size_t component, std::size_t worst) {
  const ComponentSeries c = component_series(s.points[source][component]);
  const double t0 = s.t_first_s, t1 = s.t_last_s, span = std::max(t1 - t0, 1e-3);
  const double y_max = value_range(c.innovation, c.sigma), gap = gap_threshold_s(c.innovation, span);
  const auto sigma = svg::mean_per_column(c.sigma, t0, t1, kSigmaColumns);
  const double sigma_gap = std::max(gap, 2.0 * span / kSigmaColumns);  // the band's points are a column apart
  std::string data = "<path class=\"s3\" d=\"" + svg::band_path(sigma, t0, sigma_gap, 3.0, y_max) + "\"/>";
  data += "<path class=\"s1\" d=\"" + svg::band_path(sigma, t0, sigma_gap, 1.0, y_max) + "\"/>";
  data += "<path class=\"inno\" d=\"" +
          svg::line_path(svg::min_max_per_column(c.innovation, t0, t1, kInnovationColumns), t0, gap, y_max) + "\"/>";
  if (!c.rejected.empty()) {
    data += "<path class=\"rej\" d=\"" +
            svg::dot_path(svg::min_max_per_column(c.rejected, t0, t1, kInnovationColumns), t0, y_max) + "\"/>";
  }
  svg::TimePlot plot;
  plot.title = std::string(kInnovationComponentNames[source][component]) + " [" + kInnovationUnits[source] + "]";
  plot.note = "NIS " + nis_cell(c.stats) + " per component, mean " + format_number("%.2f", c.stats.mean_z()) +
              " sigma, " + std::to_string(c.stats.rejected) + " of " + std::to_string(c.stats.count) + " rejected";
  plot.span_s = span;
  plot.y_max = y_max;
  plot.shading = phase_shading(worst);
  plot.data = std::move(data);
  return svg::time_plot(plot);
}

// Under the source's name: its NIS over the flight and where it is worst;
// `worst` is that phase when it stands out (shaded), else kPhaseCount.
std::string source_summary(const InnovationStats& st, std::size_t source, std::size_t& worst) {
  worst = kPhaseCount;
  if (source >= kSources) return "a pseudo-measurement: not scored";
  std::string out = "NIS per component " + nis_cell(st.source[source]) + " over the flight";
  double ratio = 0.0;
  const std::size_t p = worst_phase(st, source, ratio);
  if (p == kPhaseCount) return out;
  out += "; worst while " + std::string(kPhaseNames[p]) + ": " + nis_cell(st.by_phase[source][p]) + " (" +
         format_number("%.1f", ratio) + "x its average";
  if (ratio < kStandsOut) return out + ", alike in every phase)";
  worst = p;
  return out + ", shaded)";
}

std::string innovations_intro(const InnovationSeries& s) {
  std::string out = "<p>Each aiding source's innovation (measurement minus prediction) per component against time, in "
                    "the band of the filter's own predicted sigma (&plusmn;1&sigma; dark, &plusmn;3&sigma; light): when "
                    "the model is right about 68 % of the innovations lie inside &plusmn;1&sigma;. Time in seconds after "
                    "the first solution (t0 = ";
  out += format_number("%.3f", s.t_first_s) + " s on the data's clock). The strip along the top of each plot is the "
         "flight phase; the phase where a source fits worst, when it stands out (" + format_number("%.3g", kStandsOut) +
         "x the source's average NIS or more), is shaded over the whole plot.</p>\n";
  return out;
}

std::string toolbar() {
  return "<div class=\"toolbar\">" + phase_legend() +
         "<span><i class=\"sw band\"></i>&plusmn;1&sigma; / &plusmn;3&sigma;</span><span><i class=\"dot\"></i>rejected"
         "</span><span class=\"zoom\"><button type=\"button\" data-zoom=\"in\">zoom in</button><button type=\"button\" "
         "data-zoom=\"out\">zoom out</button><button type=\"button\" data-zoom=\"all\">whole flight</button> "
         "<span id=\"view\"></span> drag: pan, ctrl + wheel: zoom, double-click: whole flight</span></div>\n";
}

std::string innovations_section(const Diagnosis& d) {
  const InnovationSeries& s = d.baseline_innovations;
  std::string out = "<section id=\"innovations\"><h2>Innovations of the baseline model</h2>\n";
  bool any = false;
  for (std::size_t k = 0; k < est::kAidingSourceCount; ++k) any = any || s.has_source(k);
  if (!any || d.rounds.empty()) return out + "<p>No innovations: the baseline replay fused no measurement.</p></section>\n";
  out += innovations_intro(s) + phase_defs(s, std::max(s.t_last_s - s.t_first_s, 1e-3)) + toolbar();
  for (std::size_t k = 0; k < est::kAidingSourceCount; ++k) {
    if (!s.has_source(k)) {
      if (k < kSources) out += "<p class=\"none\">" + escape(kSourceNames[k]) + ": no innovations in this flight.</p>\n";
      continue;
    }
    std::size_t worst = kPhaseCount;
    const std::string summary = source_summary(d.rounds.front().stats, k, worst);
    out += "<h3>" + escape(est::kAidingSourceNames[k]) + " <small>" + escape(summary) + "</small></h3>\n";
    for (std::size_t i = 0; i < kMaxInnovationRows; ++i)
      if (!s.points[k][i].empty()) out += component_plot(s, k, i, worst);
  }
  return out + "</section>\n";
}

// ---- NIS per source and flight phase --------------------------------------

std::string nis_td(const ComponentStats& c) {
  return "<td class=\"" + nis_class(c) + "\">" + nis_cell(c) + " <small>" + std::to_string(c.count) + "</small></td>";
}

std::string nis_table(const InnovationStats& st) {
  std::string out = "<table><tr><th>phase</th>";
  for (const char* s : kSourceNames) out += "<th>" + escape(s) + "</th>";
  out += "</tr><tr><th>whole flight</th>";
  for (const ComponentStats& c : st.source) out += nis_td(c);
  out += "</tr>";
  for (std::size_t p = 0; p < kPhaseCount; ++p) {
    out += "<tr><td><i class=\"sw " + phase_class(p) + "\"></i>" + escape(kPhaseNames[p]) + "</td>";
    for (std::size_t k = 0; k < kSources; ++k) out += nis_td(st.by_phase[k][p]);
    out += "</tr>";
  }
  return out + "</table>\n";
}

std::string nis_chart(const InnovationStats& st) {
  std::vector<svg::BarGroup> groups;
  for (std::size_t k = 0; k < kSources; ++k) {
    if (!st.source[k].count) continue;
    svg::BarGroup g{kSourceNames[k], {}};
    g.bars.push_back({st.source[k].nis(), "all", "whole flight: NIS " + nis_cell(st.source[k])});
    for (std::size_t p = 0; p < kPhaseCount; ++p) {
      const ComponentStats& c = st.by_phase[k][p];
      g.bars.push_back({c.nis(), phase_class(p),
                        std::string(kPhaseNames[p]) + ": NIS " + nis_cell(c) + ", " + std::to_string(c.count) + " components"});
    }
    groups.push_back(std::move(g));
  }
  return svg::grouped_bars(groups, "NIS per component", 1.0);
}

std::string nis_section(const Diagnosis& d) {
  std::string out = "<section id=\"nis\"><h2>NIS per source and flight phase</h2>\n";
  if (d.rounds.empty()) return out + "</section>\n";
  const InnovationStats& st = d.rounds.front().stats;
  out += "<p>The baseline model's NIS per innovation component (mean of (y/&sigma;)&sup2;; 1 when the model is right, the "
         "dashed line) over the whole flight (dark bar) and per flight phase, with the number of components. A missing "
         "effect shows where the vehicle excites it; a noise level set wrong, alike in every phase. Worst fit: " +
         escape(worst_cell(st)) + ".</p>\n";
  out += "<div class=\"legend\"><span><i class=\"sw all\"></i>whole flight</span>" + phase_legend() + "</div>\n";
  return out + nis_chart(st) + nis_table(st) + "</section>\n";
}

// ---- the candidates' evidence ---------------------------------------------

std::string verdict_class(const CandidateResult& c, double min_significance) {
  if (c.explains(min_significance)) return "explains";
  return c.implausible_fit(min_significance) ? "implausible" : "no";
}

std::string verdict_text(const CandidateResult& c, double min_significance) {
  if (c.explains(min_significance)) return "explains the data";
  return c.implausible_fit(min_significance) ? "fits, but implausibly large" : "no";
}

std::string estimate_cell(const CandidateResult& c) {
  std::string out;
  for (std::size_t i = 0; i < c.estimate.size(); ++i) {
    const char* name = est::effect_component_name(c.effect, static_cast<Eigen::Index>(i));
    out += "<span class=\"c\">";
    if (*name) out += escape(name) + ": ";
    out += escape(estimate_component_text(c, i, "\u00b1")) + "</span>";
  }
  return out;
}

std::string candidate_row(const CandidateResult& c, double min_significance) {
  std::string out = "<tr class=\"" + verdict_class(c, min_significance) + "\"><td>" +
                    escape(candidate_name(c)) + "</td><td class=\"v\">" + escape(verdict_text(c, min_significance)) + "</td>";
  out += "<td>" + format_number("%.1f", c.nll_gain) + "</td><td>" + format_number("%.1f", c.evidence_threshold) + "</td><td>" +
         format_number("%.1f", c.significance) + "</td><td class=\"est\">" + estimate_cell(c) + "</td><td>" +
         escape(est::spec(c.effect).unit) + "</td><td class=\"nw\">";
  for (std::size_t k = 0; k < kSources; ++k) {
    if (k) out += " / ";
    out += nis_cell(c.stats.source[k]);
  }
  return out + "</td><td>" + rmse_text(c.rmse_pos_h_m, "m") + "</td></tr>";
}

std::string round_evidence(const Round& round, std::size_t index, double min_significance) {
  std::string out = "<h3>Round " + std::to_string(index + 1) + ": each candidate added to (" +
                    escape(effect_list(round.model)) + ")</h3>\n";
  std::vector<svg::PairRow> rows;
  for (const CandidateResult& c : round.candidates)
    rows.push_back({candidate_name(c), c.nll_gain, c.evidence_threshold, verdict_class(c, min_significance)});
  out += "<div class=\"legend\"><span><i class=\"sw explains\"></i>log-likelihood gain: explains the data</span>"
         "<span><i class=\"sw implausible\"></i>fits, but implausibly large</span><span><i class=\"sw no\"></i>does not "
         "explain it</span><span><i class=\"sw penalty\"></i>threshold</span></div>\n";
  out += svg::paired_bars(rows);
  out += "<table><tr><th>effect</th><th>verdict</th><th>log-likelihood gain</th><th>threshold</th>"
         "<th>max |estimate &minus; assumed| / &sigma;</th><th class=\"est\">estimate &plusmn; &sigma;</th><th>unit</th>"
         "<th>NIS pos / vel / mag</th>"
         "<th>horizontal RMSE vs truth</th></tr>";
  for (const CandidateResult& c : round.candidates) out += candidate_row(c, min_significance);
  return out + "</table>\n";
}

std::string candidates_section(const DiagnoseOptions& o, const Diagnosis& d) {
  std::string out = "<section id=\"candidates\"><h2>Candidate effects: the evidence</h2>\n<p>Each candidate is a replay "
                    "with its states added. It explains the data when the innovations' log-likelihood rises by more "
                    "than the threshold, a log Bayes factor of " + format_number("%.2g", o.min_log_evidence) +
                    " (the states start from their prior, so the likelihood already pays for them; the thick bar "
                    "beyond the thin one; symmetric log scale), its estimate is at least " + format_number("%.3g", o.min_significance) +
                    " &sigma; from the value assumed without it, and a real unit can have it.</p>\n";
  bool any = false;
  for (std::size_t r = 0; r < d.rounds.size(); ++r) {
    if (d.rounds[r].candidates.empty()) continue;
    any = true;
    out += round_evidence(d.rounds[r], r, o.min_significance);
  }
  if (!any) out += "<p>No candidate was tried.</p>\n";
  const std::vector<std::string> implausible = implausible_fits(d, o.min_significance);
  if (!implausible.empty()) out += "<p>Not named:</p>" + list_items(implausible);
  return out + "</section>\n";
}

// ---- before and after -----------------------------------------------------

std::string metric_row(const std::string& name, const std::vector<std::string>& cells) {
  std::string out = "<tr><td>" + name + "</td>";
  for (const std::string& c : cells) out += "<td>" + c + "</td>";
  return out + "</tr>";
}

std::string comparison_table(const Round& before, const Round& after, bool changed) {
  std::vector<const Round*> runs = {&before};
  if (changed) runs.push_back(&after);
  auto cells = [&](auto f) {
    std::vector<std::string> out;
    for (const Round* r : runs) out.push_back(f(*r));
    return out;
  };
  std::string out = "<table><tr><th></th><th>before: baseline</th>" +
                    std::string(changed ? "<th>after: with the effects found</th>" : "") + "</tr>";
  out += metric_row("model", cells([](const Round& r) { return escape(effect_list(r.model)); }));
  out += metric_row("horizontal RMSE vs truth", cells([](const Round& r) { return rmse_text(r.rmse_pos_h_m, "m"); }));
  out += metric_row("attitude RMSE vs truth", cells([](const Round& r) { return rmse_text(r.rmse_att_deg, "deg"); }));
  out += metric_row("outage drift (RMS of the largest horizontal drift per --outage window)",
                    cells([](const Round& r) { return rmse_text(r.outage_drift_h_m, "m"); }));
  for (std::size_t k = 0; k < kSources; ++k) {
    out += metric_row("NIS per component, " + escape(kSourceNames[k]),
                      cells([k](const Round& r) { return nis_cell(r.stats.source[k]); }));
  }
  for (std::size_t k = 0; k < kSources; ++k) {
    out += metric_row("innovation whiteness, " + escape(kSourceNames[k]) + " (lag-1 autocorrelation, 0 when white)",
                      cells([k](const Round& r) {
                        return r.stats.source[k].count ? format_number("%.2f", r.stats.source[k].lag1()) : "-";
                      }));
  }
  out += metric_row("innovations' negative log-likelihood",
                    cells([](const Round& r) { return format_number("%.1f", r.stats.total_nll()); }));
  return out + "</table>\n";
}

std::string comparison_section(const Diagnosis& d) {
  std::string out = "<section id=\"comparison\"><h2>Before and after</h2>\n";
  if (d.rounds.empty()) return out + "</section>\n";
  const bool changed = d.model_changed();
  out += changed ? "<p>The baseline model against the final one (the effects found added).</p>\n"
                 : "<p>No effect was added: the baseline is the final model.</p>\n";
  out += comparison_table(d.rounds.front(), d.rounds.back(), changed);
  return out + "<p class=\"note\">n/a: no truth.csv (RMSE), no --outage windows (drift).</p></section>\n";
}

std::string findings_section(const Diagnosis& d) {
  std::string out = "<section id=\"findings\"><h2>Noise levels and what the flight could not show</h2>\n";
  std::vector<std::string> noise = tuned_noise_findings(d);
  if (const std::string p = process_noise_text(d); !p.empty()) noise.push_back(p);
  if (const std::string u = uncalibrated_text(d); !u.empty()) noise.push_back(u);
  noise.insert(noise.end(), d.noise_findings.begin(), d.noise_findings.end());
  out += "<h3>Noise findings</h3>";
  out += noise.empty() ? "<p>Every source's NIS per component is within 0.7-1.3: its innovations are as large as its "
                         "sigma claims, the noise levels fit.</p>\n"
                       : list_items(noise);
  if (!d.skipped.empty()) {
    std::vector<std::string> skipped;
    for (const Diagnosis::Skipped& s : d.skipped) skipped.push_back(std::string(est::spec(s.effect).name) + ": " + s.reason);
    out += "<h3>Not tested: the data cannot tell</h3>" + list_items(skipped);
  }
  if (!d.observability.empty()) out += "<h3>Weakly observable in this flight</h3>" + list_items(d.observability);
  if (!d.model_file.empty()) {
    out += "<p>Applied: " + escape(d.model_file) +
           " (start the next flight from it: --model-file, or navigation.model_file).</p>\n";
  }
  return out + "</section>\n";
}

// ---- the page -------------------------------------------------------------

std::string style() {
  std::string css =
      "body{font:14px/1.45 system-ui,-apple-system,'Segoe UI',Roboto,sans-serif;color:#222;max-width:1180px;"
      "margin:0 auto;padding:0 20px 48px}h1{font-size:21px;margin:18px 0 6px}h2{font-size:17px;margin:30px 0 8px;"
      "border-bottom:1px solid #ddd;padding-bottom:3px}h3{font-size:14px;margin:16px 0 2px}h3 small{font-weight:normal;"
      "color:#555}.meta{color:#555;margin:0 0 10px}.conclusion{font-size:15.5px;padding:10px 14px;"
      "border-left:5px solid #009e73;background:#eef8f4}.conclusion.found{border-color:#d55e00;background:#fcf1ea}"
      ".conclusion.noise{border-color:#e69f00;background:#fdf6e8}figure{margin:0}svg.plot{display:block;width:100%;"
      "height:auto}svg.defs{position:absolute}svg text{font:11px system-ui,sans-serif;fill:#333}svg .ttl{font-size:12px;"
      "font-weight:600}svg .note,svg .val{fill:#555}svg .glabel,svg .rlabel{font-size:12px}.grid{stroke:#e6e6e6}"
      ".zero{stroke:#999}.frame{fill:none;stroke:#999}.ref{stroke:#d55e00;stroke-width:1.5;stroke-dasharray:6 4}"
      ".zx path{vector-effect:non-scaling-stroke}.inno{fill:none;stroke:#1b1b1b;stroke-width:.7;stroke-linejoin:round}"
      ".s1{fill:#0072b2;fill-opacity:.25}.s3{fill:#0072b2;fill-opacity:.10}.rej{fill:none;stroke:#d55e00;"
      "stroke-width:5;stroke-linecap:round}.ph.strip{opacity:.85}.ph.worst{opacity:.22}figure.tplot svg{cursor:grab;"
      "touch-action:pan-y}.toolbar{position:sticky;top:0;z-index:1;background:#fff;border-bottom:1px solid #eee;"
      "padding:6px 0;display:flex;flex-wrap:wrap;gap:4px 14px;align-items:center;font-size:13px}.zoom{color:#555}"
      ".zoom button{margin-right:4px}.legend{display:flex;gap:14px;flex-wrap:wrap;font-size:13px}"
      "i.sw{display:inline-block;width:14px;height:10px;margin-right:4px;vertical-align:baseline;"
      "border:1px solid rgba(0,0,0,.2)}i.sw.band{background:rgba(0,114,178,.3)}i.sw.all,rect.all{background:#444;"
      "fill:#444}i.dot{display:inline-block;width:8px;height:8px;border-radius:4px;background:#d55e00;margin-right:4px}"
      "table{border-collapse:collapse;margin:8px 0;font-size:13px}td,th{border:1px solid #ddd;padding:3px 8px;"
      "text-align:right;vertical-align:top}th{background:#f5f5f5}td:first-child,th:first-child{text-align:left}"
      "td.est,th.est{text-align:left}td small{color:#777}td.ok{background:#e6f4ea}td.low{background:#e3eefb}"
      "td.high{background:#fdf0dc}td.vhigh{background:#f9d5d2}tr.explains td:nth-child(2){color:#00734f;"
      "font-weight:600}tr.implausible td:nth-child(2){color:#a86b00}rect.explains{fill:#009e73}"
      "rect.implausible{fill:#e69f00}rect.no{fill:#b0b0b0}rect.penalty{fill:#333}i.sw.explains{background:#009e73}"
      "i.sw.implausible{background:#e69f00}i.sw.no{background:#b0b0b0}i.sw.penalty{background:#333;height:5px}"
      "td.est span.c{display:inline-block;min-width:11em;margin-right:.8em}td.est{white-space:normal;min-width:24em}"
      "td.nw{white-space:nowrap}td.v{text-align:left}p.none,.note{color:#666}";
  for (std::size_t p = 0; p < kPhaseCount; ++p) {
    const std::string c = phase_class(p);
    css += "i.sw." + c + "{background:" + kPhaseColours[p] + "}rect." + c + "{fill:" + kPhaseColours[p] + "}";
  }
  return "<style>" + css + "</style>\n";
}

// Zoom and pan of every time plot together (the nested <svg class="zx">
// viewBoxes), the time ticks redrawn for the view; body[data-ok] = 1 when it
// has run, body[data-errors] counts script errors.
constexpr const char* kScript = R"JS(<script>
(function () {
  'use strict';
  var body = document.body, errors = 0;
  window.addEventListener('error', function () { errors += 1; body.setAttribute('data-errors', String(errors)); });
  var figs = Array.prototype.slice.call(document.querySelectorAll('figure.tplot'));
  var span = figs.length ? parseFloat(figs[0].getAttribute('data-span')) : 1;
  var view = [0, span], minWidth = span / 400, readout = document.getElementById('view');
  function niceStep(width, count) {
    var raw = width / count, magnitude = Math.pow(10, Math.floor(Math.log10(raw))), m = raw / magnitude;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * magnitude;
  }
  function label(v) { return String(parseFloat(v.toPrecision(6))); }
  function element(parent, name, attrs, text) {
    var e = document.createElementNS(parent.namespaceURI, name);
    Object.keys(attrs).forEach(function (k) { e.setAttribute(k, String(attrs[k])); });
    if (text !== undefined) e.textContent = text;
    parent.appendChild(e);
  }
  function ticks(fig) {
    var g = fig.querySelector('g.xt');
    var x0 = +g.getAttribute('data-x'), y0 = +g.getAttribute('data-y');
    var w = +g.getAttribute('data-w'), h = +g.getAttribute('data-h');
    while (g.firstChild) g.removeChild(g.firstChild);
    var width = view[1] - view[0], step = niceStep(width, 10);
    for (var k = Math.ceil(view[0] / step - 1e-9); k * step <= view[1] + 1e-9 * step; k += 1) {
      var x = x0 + (k * step - view[0]) / width * w;
      element(g, 'line', { 'class': 'grid', x1: x, x2: x, y1: y0, y2: y0 + h });
      element(g, 'text', { 'class': 'tick', 'text-anchor': 'middle', x: x, y: y0 + h + 14 }, label(k * step));
    }
  }
  function draw() {
    figs.forEach(function (fig) {
      fig.querySelectorAll('svg.zx').forEach(function (s) {
        s.viewBox.baseVal.x = view[0];
        s.viewBox.baseVal.width = view[1] - view[0];
      });
      ticks(fig);
    });
    if (readout) readout.textContent = label(view[0]) + ' - ' + label(view[1]) + ' s';
  }
  function setView(a, b) {
    var w = Math.min(span, Math.max(b - a, minWidth));
    a = Math.max(0, Math.min(a, span - w));
    view = [a, a + w];
    draw();
  }
  function zoom(factor, at) {
    var w = view[1] - view[0], c = view[0] + at * w;
    setView(c - at * w * factor, c + (1 - at) * w * factor);
  }
  figs.forEach(function (fig) {
    var plot = fig.querySelector('svg.plot'), area = fig.querySelector('svg.zx'), drag = null;
    function at(e) {
      var r = area.getBoundingClientRect();
      return Math.min(1, Math.max(0, (e.clientX - r.left) / r.width));
    }
    plot.addEventListener('wheel', function (e) {
      if (!e.ctrlKey && !e.shiftKey) return;
      e.preventDefault();
      zoom(e.deltaY > 0 ? 1.25 : 0.8, at(e));
    }, { passive: false });
    plot.addEventListener('pointerdown', function (e) {
      drag = { x: e.clientX, view: view.slice(), width: area.getBoundingClientRect().width };
      plot.setPointerCapture(e.pointerId);
    });
    plot.addEventListener('pointermove', function (e) {
      if (!drag) return;
      var dt = (drag.x - e.clientX) / drag.width * (drag.view[1] - drag.view[0]);
      setView(drag.view[0] + dt, drag.view[1] + dt);
    });
    plot.addEventListener('pointerup', function () { drag = null; });
    plot.addEventListener('dblclick', function () { setView(0, span); });
  });
  document.querySelectorAll('button[data-zoom]').forEach(function (b) {
    b.addEventListener('click', function () {
      var how = b.getAttribute('data-zoom');
      if (how === 'all') setView(0, span); else zoom(how === 'in' ? 0.5 : 2, 0.5);
    });
  });
  draw();
  body.setAttribute('data-plots', String(figs.length));
  body.setAttribute('data-ok', '1');
})();
</script>
)JS";

std::string conclusion_class(const Diagnosis& d) {
  if (d.model_changed() || !d.carried.empty()) return "conclusion found";
  return d.noise_findings.empty() ? "conclusion" : "conclusion noise";
}

}  // namespace

std::string diagnosis_html(const DiagnoseOptions& o, const Diagnosis& d) {
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                     "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>sinu diagnose: ";
  page += escape(o.replay.in_dir) + "</title>\n" + style() + "</head>\n<body data-ok=\"0\">\n";
  page += "<h1>sinu diagnose: " + escape(o.replay.in_dir) + "</h1>\n";
  page += "<p class=\"meta\">Baseline model: " +
          escape(d.rounds.empty() ? effect_list(o.replay.unit.effects) : effect_list(d.rounds.front().model)) +
          ". report.md and diagnosis.json beside this page hold the same numbers.</p>\n";
  page += "<p id=\"conclusion\" class=\"" + conclusion_class(d) + "\">" + escape(conclusion_sentence(d)) + "</p>\n";
  page += innovations_section(d) + nis_section(d) + candidates_section(o, d) + comparison_section(d) +
          findings_section(d);
  page += kScript;
  return page + "</body></html>\n";
}

bool write_diagnosis_html(const DiagnoseOptions& o, const Diagnosis& d, std::string& error) {
  const std::string path = o.out_dir + "/report.html";
  std::ofstream out(path, std::ios::binary);
  out << diagnosis_html(o, d);
  if (!out) {
    error = path + ": cannot write";
    return false;
  }
  return true;
}

}  // namespace sinu::diagnose
