// report.html of `sinu diagnose`, the writer alone on a hand-made diagnosis:
// escaping, a source without innovations, a flight without truth, the
// conclusion in the printed summary's own words, the plots' reduction.
// (test_diagnose_html_browser.cpp opens a real diagnosis's page in Chromium.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "firmware/host/diagnose/diagnosis_html.hpp"
#include "firmware/host/diagnose/diagnosis_report.hpp"
#include "firmware/host/diagnose/diagnosis_text.hpp"
#include "firmware/host/diagnose/svg_plot.hpp"

namespace sinu::test {
namespace {

using diagnose::CandidateResult;
using diagnose::Diagnosis;
using diagnose::DiagnoseOptions;
using diagnose::Round;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

bool references_outside(const std::string& html) {
  return html.find("http://") != std::string::npos || html.find("https://") != std::string::npos ||
         html.find("src=") != std::string::npos || html.find("url(") != std::string::npos ||
         html.find("@import") != std::string::npos;
}

// Innovations of one source: `n` fixes at 5 Hz, three components, sigma 1, a
// misfit that grows in the turn (t0 + 20..40 s), one rejected fix.
void add_innovations(diagnose::InnovationSeries& s, est::AidingSource source, int n) {
  const auto k = static_cast<std::size_t>(source);
  for (int i = 0; i < n; ++i) {
    const double t = 1000.0 + 0.2 * i;
    const double y = std::sin(0.7 * i) * (t > 1020.0 && t < 1040.0 ? 3.0 : 0.8);
    for (std::size_t c = 0; c < 3; ++c) s.points[k][c].push_back({t, static_cast<float>(y), 1.0f, i != 17});
  }
  s.t_first_s = 1000.0;
  s.t_last_s = 1000.0 + 0.2 * (n - 1);
  s.phases = {{1000.0, 1020.0, diagnose::Phase::Straight}, {1020.0, 1040.0, diagnose::Phase::Turning},
              {1040.0, s.t_last_s, diagnose::Phase::Straight}};
}

void add_stats(diagnose::InnovationStats& st, double scale) {
  for (int i = 0; i < 300; ++i) {
    const double y = scale * std::sin(0.7 * i);
    st.source[0].add(y, 1.0, true);
    st.by_phase[0][i < 100 ? 1 : 0].add(y * (i < 100 ? 2.0 : 1.0), 1.0, true);
  }
}

// A flight without truth and without a magnetometer whose diagnosis found a
// lever arm; the dataset's name and a finding need escaping.
struct HandMade {
  DiagnoseOptions o;
  Diagnosis d;
  HandMade() {
    o.replay.in_dir = "flights/<b>\"7\" & 'x'</b>";
    Round before;
    before.model.add(est::Effect::GpsLatency);
    add_stats(before.stats, 1.5);
    CandidateResult c;
    c.effect = est::Effect::LeverArm;
    c.nll_gain = 52.5;
    c.evidence_threshold = 4.6;
    c.significance = 12.0;
    c.estimate = {0.9, -0.5, -0.6};
    c.sigma = {0.05, 0.06, 0.04};
    c.plausibility = 0.3;
    c.stats = before.stats;
    CandidateResult other = c;
    other.effect = est::Effect::GpsLatency;
    other.nll_gain = -3.0;
    other.estimate = {0.05};
    other.sigma = {0.01};
    before.candidates = {c, other};
    before.found = true;
    Round after;
    after.model = before.model;
    after.model.add(est::Effect::LeverArm);
    add_stats(after.stats, 1.0);
    d.rounds = {before, after};
    d.missing = {est::Effect::LeverArm};
    d.noise_findings = {"gnss_position: NIS <1.5> & more"};
    add_innovations(d.baseline_innovations, est::AidingSource::GnssPosition, 500);
  }
};

TEST(DiagnoseHtml, TextIsEscapedAndNothingOutsideTheFileIsReferenced) {
  const HandMade h;
  const std::string html = diagnose::diagnosis_html(h.o, h.d);
  EXPECT_EQ(html.find("<b>\"7\""), std::string::npos);
  EXPECT_NE(html.find("flights/&lt;b&gt;&quot;7&quot; &amp; &#39;x&#39;&lt;/b&gt;"), std::string::npos);
  EXPECT_NE(html.find("gnss_position: NIS &lt;1.5&gt; &amp; more"), std::string::npos);
  EXPECT_FALSE(references_outside(html));
  // The only references are to the page's own phase shading.
  EXPECT_EQ(count(html, "href=\""), count(html, "href=\"#phase-"));
}

TEST(DiagnoseHtml, TheConclusionIsTheSummarysOwnWords) {
  const HandMade h;
  const std::string html = diagnose::diagnosis_html(h.o, h.d), summary = diagnose::diagnosis_summary(h.o, h.d);
  const std::string missing = diagnose::missing_effect_text(h.d.rounds.front().candidates.front());
  const std::string before_after = diagnose::before_after_text(h.d.rounds.front(), h.d.rounds.back());
  EXPECT_NE(summary.find("missing effect: " + missing), std::string::npos) << summary;
  EXPECT_NE(summary.find("error before -> after: " + before_after), std::string::npos) << summary;
  const std::string conclusion = diagnose::conclusion_sentence(h.d);
  EXPECT_EQ(conclusion, "Missing effect: " + missing + ". Error before -> after: " + before_after + ".");
  // First thing on the page, after the title.
  const std::size_t at = html.find("<p id=\"conclusion\"");
  ASSERT_NE(at, std::string::npos);
  EXPECT_LT(at, html.find("<section"));
  EXPECT_NE(html.find(diagnose::svg::escape(conclusion), at), std::string::npos);
}

TEST(DiagnoseHtml, ASourceWithoutInnovationsAndAFlightWithoutTruthAreSaidSo) {
  const HandMade h;
  const std::string html = diagnose::diagnosis_html(h.o, h.d);
  EXPECT_NE(html.find("magnetometer: no innovations in this flight."), std::string::npos);
  EXPECT_NE(html.find("gnss_velocity: no innovations in this flight."), std::string::npos);
  EXPECT_EQ(count(html, "<figure class=\"tplot\""), 3u);  // north, east, down of gnss_position
  EXPECT_NE(html.find("<td>horizontal RMSE vs truth</td><td>n/a</td><td>n/a</td>"), std::string::npos);
  // The turn, where the misfit is, stands out and is shaded over the whole plot.
  EXPECT_NE(html.find("worst while turning"), std::string::npos);
  EXPECT_NE(html.find("<use href=\"#phase-1\" class=\"ph worst\"/>"), std::string::npos);
  // Each candidate: its bars and its row.
  EXPECT_EQ(count(html, "<tr class=\"explains\">"), 1u);
  EXPECT_EQ(count(html, "<rect class=\"explains\""), 1u);
}

TEST(DiagnoseHtml, NothingFoundAndNoInnovationsStillMakeAPage) {
  DiagnoseOptions o;
  o.replay.in_dir = "empty";
  Diagnosis d;
  Round r;
  d.rounds = {r};
  const std::string html = diagnose::diagnosis_html(o, d);
  EXPECT_NE(html.find("The model explains the data"), std::string::npos);
  EXPECT_NE(html.find("No innovations: the baseline replay fused no measurement."), std::string::npos);
  EXPECT_NE(html.find("No effect was added: the baseline is the final model."), std::string::npos);
  EXPECT_EQ(count(html, "<figure"), 0u);
  EXPECT_NE(html.find("</html>"), std::string::npos);
}

TEST(DiagnoseHtml, APlotKeepsAtMostTwoPointsPerColumnAndEveryExtreme) {
  std::vector<diagnose::svg::Sample> samples;
  for (int i = 0; i < 1000000; ++i) samples.push_back({0.01 * i, std::sin(0.001 * i)});
  samples[123456].y = 50.0;  // a spike must survive the reduction
  const auto reduced = diagnose::svg::min_max_per_column(samples, 0.0, 10000.0, 2000);
  EXPECT_LE(reduced.size(), 4000u);
  EXPECT_GE(reduced.size(), 3000u);
  bool spike = false;
  for (std::size_t i = 0; i < reduced.size(); ++i) {
    spike = spike || reduced[i].y == 50.0;
    if (i) {
      EXPECT_LE(reduced[i - 1].t_s, reduced[i].t_s);
    }
  }
  EXPECT_TRUE(spike);
  // Few samples are kept as they are.
  EXPECT_EQ(diagnose::svg::min_max_per_column(std::span(samples).first(100), 0.0, 1.0, 2000).size(), 100u);
  EXPECT_EQ(diagnose::svg::nice_ticks(0.0, 600.0, 10), (std::vector<double>{0, 50, 100, 150, 200, 250, 300, 350, 400,
                                                                             450, 500, 550, 600}));
}

}  // namespace
}  // namespace sinu::test
