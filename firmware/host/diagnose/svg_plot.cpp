#include "firmware/host/diagnose/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sinu::diagnose::svg {

namespace {

// Time plots: the whole figure, and the plot area inside it [px of the viewBox].
constexpr double kPlotWidthPx = 1000.0, kPlotHeightPx = 152.0;
constexpr double kAreaLeftPx = 64.0, kAreaTopPx = 22.0, kAreaWidthPx = 926.0, kAreaHeightPx = 108.0;

// Seconds in path data: centiseconds are finer than any zoom the page allows.
std::string seconds(double t_s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", t_s);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string point(double t_s, double y) { return seconds(t_s) + "," + number(y, 4); }

std::string attr(const char* name, double v) { return std::string(" ") + name + "=\"" + number(v, 6) + "\""; }

std::size_t column_of(double t_s, double t0_s, double t1_s, int columns) {
  const double u = (t_s - t0_s) / (t1_s - t0_s) * columns;
  return static_cast<std::size_t>(std::clamp(u, 0.0, static_cast<double>(columns - 1)));
}

// Consecutive runs of samples in one column: [begin, end) index pairs.
template <typename F>
void for_each_column(std::span<const Sample> samples, double t0_s, double t1_s, int columns, F&& f) {
  std::size_t begin = 0;
  while (begin < samples.size()) {
    const std::size_t col = column_of(samples[begin].t_s, t0_s, t1_s, columns);
    std::size_t end = begin + 1;
    while (end < samples.size() && column_of(samples[end].t_s, t0_s, t1_s, columns) == col) ++end;
    f(samples.subspan(begin, end - begin));
    begin = end;
  }
}

std::string y_axis(double y_max, double to_px) {
  std::string out = "<g class=\"yt\">";
  for (const double v : nice_ticks(-y_max, y_max, 5)) {
    const double y = kAreaTopPx + (y_max - v) * to_px;
    out += "<line class=\"" + std::string(v == 0.0 ? "zero" : "grid") + "\"" + attr("x1", kAreaLeftPx) +
           attr("x2", kAreaLeftPx + kAreaWidthPx) + attr("y1", y) + attr("y2", y) + "/>";
    out += "<text class=\"tick\" text-anchor=\"end\"" + attr("x", kAreaLeftPx - 6.0) + attr("y", y + 4.0) + ">" +
           number(v, 3) + "</text>";
  }
  return out + "</g>";
}

std::string x_axis(double span_s) {
  std::string out = "<g class=\"xt\"" + attr("data-x", kAreaLeftPx) + attr("data-y", kAreaTopPx) +
                    attr("data-w", kAreaWidthPx) + attr("data-h", kAreaHeightPx) + ">";
  for (const double t : nice_ticks(0.0, span_s, 10)) {
    const double x = kAreaLeftPx + t / span_s * kAreaWidthPx;
    out += "<line class=\"grid\"" + attr("x1", x) + attr("x2", x) + attr("y1", kAreaTopPx) +
           attr("y2", kAreaTopPx + kAreaHeightPx) + "/>";
    out += "<text class=\"tick\" text-anchor=\"middle\"" + attr("x", x) + attr("y", kAreaTopPx + kAreaHeightPx + 14.0) +
           ">" + number(t, 6) + "</text>";
  }
  return out + "</g>";
}

// A nested <svg> over the plot area whose viewBox is the data's: the page's script zooms it.
std::string zoomable_layer(double y0, double height, const std::string& content, double span_s) {
  return "<svg class=\"zx\" preserveAspectRatio=\"none\"" + attr("x", kAreaLeftPx) + attr("y", kAreaTopPx) +
         attr("width", kAreaWidthPx) + attr("height", kAreaHeightPx) + " viewBox=\"0 " + number(y0, 6) + " " +
         number(span_s, 8) + " " + number(height, 6) + "\">" + content + "</svg>";
}

double symlog(double v) { return std::copysign(std::log10(1.0 + std::abs(v)), v); }

}  // namespace

std::string escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string number(double v, int significant) {
  if (!std::isfinite(v)) return "0";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", significant, v);
  return std::string(buf) == "-0" ? "0" : buf;
}

std::vector<double> nice_ticks(double lo, double hi, int count) {
  std::vector<double> out;
  if (!(hi > lo) || count < 1) return out;
  const double raw = (hi - lo) / count, magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double m = raw / magnitude;
  const double step = (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * magnitude;
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k += 1.0) out.push_back(k * step);
  return out;
}

std::vector<Sample> min_max_per_column(std::span<const Sample> samples, double t0_s, double t1_s, int columns) {
  if (samples.size() <= 2 * static_cast<std::size_t>(columns) || !(t1_s > t0_s))
    return {samples.begin(), samples.end()};
  std::vector<Sample> out;
  for_each_column(samples, t0_s, t1_s, columns, [&](std::span<const Sample> col) {
    const auto [lo, hi] = std::minmax_element(col.begin(), col.end(), [](const Sample& a, const Sample& b) { return a.y < b.y; });
    out.push_back(lo < hi ? *lo : *hi);
    if (lo != hi) out.push_back(lo < hi ? *hi : *lo);
  });
  return out;
}

std::vector<Sample> mean_per_column(std::span<const Sample> samples, double t0_s, double t1_s, int columns) {
  if (samples.size() <= static_cast<std::size_t>(columns) || !(t1_s > t0_s)) return {samples.begin(), samples.end()};
  std::vector<Sample> out;
  for_each_column(samples, t0_s, t1_s, columns, [&](std::span<const Sample> col) {
    Sample m;
    for (const Sample& s : col) {
      m.t_s += s.t_s;
      m.y += s.y;
    }
    const auto n = static_cast<double>(col.size());
    out.push_back({m.t_s / n, m.y / n});
  });
  return out;
}

std::string line_path(std::span<const Sample> samples, double t0_s, double gap_s, double clip) {
  std::string d;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const bool start = i == 0 || samples[i].t_s - samples[i - 1].t_s > gap_s;
    d += start ? (i ? " M" : "M") : " ";
    d += point(samples[i].t_s - t0_s, -std::clamp(samples[i].y, -clip, clip));
  }
  return d;
}

std::string dot_path(std::span<const Sample> samples, double t0_s, double clip) {
  std::string d;
  for (const Sample& s : samples) {
    d += d.empty() ? "M" : " M";
    d += point(s.t_s - t0_s, -std::clamp(s.y, -clip, clip));
    d += "h0";
  }
  return d;
}

std::string band_path(std::span<const Sample> sigma, double t0_s, double gap_s, double factor, double clip) {
  std::string d;
  std::size_t begin = 0;
  while (begin < sigma.size()) {
    std::size_t end = begin + 1;
    while (end < sigma.size() && sigma[end].t_s - sigma[end - 1].t_s <= gap_s) ++end;
    // Up along the upper edge, back along the lower one.
    for (std::size_t i = begin; i < end; ++i) {
      d += i == begin ? (d.empty() ? "M" : " M") : " ";
      d += point(sigma[i].t_s - t0_s, -std::min(factor * sigma[i].y, clip));
    }
    for (std::size_t i = end; i-- > begin;) {
      d += ' ';
      d += point(sigma[i].t_s - t0_s, std::min(factor * sigma[i].y, clip));
    }
    d += "Z";
    begin = end;
  }
  return d;
}

std::string time_plot(const TimePlot& p) {
  const double to_px = kAreaHeightPx / (2.0 * p.y_max);
  std::string out = "<figure class=\"tplot\" data-span=\"" + number(p.span_s, 8) + "\">";
  out += "<svg class=\"plot\" role=\"img\" viewBox=\"0 0 " + number(kPlotWidthPx) + " " + number(kPlotHeightPx) +
         "\"><title>" + escape(p.title) + "</title>";
  out += "<text class=\"ttl\"" + attr("x", kAreaLeftPx) + attr("y", 15.0) + ">" + escape(p.title) + "</text>";
  if (!p.note.empty()) {
    out += "<text class=\"note\" text-anchor=\"end\"" + attr("x", kAreaLeftPx + kAreaWidthPx) + attr("y", 15.0) + ">" +
           escape(p.note) + "</text>";
  }
  out += y_axis(p.y_max, to_px) + x_axis(p.span_s);
  out += zoomable_layer(0.0, 1.0, p.shading, p.span_s);
  out += zoomable_layer(-p.y_max, 2.0 * p.y_max, p.data, p.span_s);
  out += "<rect class=\"frame\"" + attr("x", kAreaLeftPx) + attr("y", kAreaTopPx) + attr("width", kAreaWidthPx) +
         attr("height", kAreaHeightPx) + "/>";
  return out + "</svg></figure>\n";
}

std::string grouped_bars(const std::vector<BarGroup>& groups, const std::string& y_label, double reference) {
  constexpr double kW = 1000.0, kH = 250.0, kLeft = 64.0, kTop = 12.0, kAreaW = 926.0, kAreaH = 196.0;
  double top = reference * 1.25;
  for (const BarGroup& g : groups)
    for (const Bar& b : g.bars) top = std::max(top, b.value * 1.08);
  const std::vector<double> ticks = nice_ticks(0.0, top, 5);
  if (!ticks.empty()) top = std::max(top, ticks.back());
  const double to_px = kAreaH / top, group_w = kAreaW / static_cast<double>(std::max<std::size_t>(1, groups.size()));
  std::string out = "<svg class=\"plot bars\" role=\"img\" viewBox=\"0 0 " + number(kW) + " " + number(kH) + "\">";
  for (const double v : ticks) {
    const double y = kTop + kAreaH - v * to_px;
    out += "<line class=\"grid\"" + attr("x1", kLeft) + attr("x2", kLeft + kAreaW) + attr("y1", y) + attr("y2", y) + "/>";
    out += "<text class=\"tick\" text-anchor=\"end\"" + attr("x", kLeft - 6.0) + attr("y", y + 4.0) + ">" + number(v, 3) +
           "</text>";
  }
  out += "<text class=\"tick\" transform=\"rotate(-90)\" text-anchor=\"middle\"" + attr("x", -(kTop + kAreaH / 2.0)) +
         attr("y", 16.0) + ">" + escape(y_label) + "</text>";
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const double x0 = kLeft + group_w * static_cast<double>(g) + 0.1 * group_w;
    const double bar_w = 0.8 * group_w / static_cast<double>(std::max<std::size_t>(1, groups[g].bars.size()));
    for (std::size_t b = 0; b < groups[g].bars.size(); ++b) {
      const Bar& bar = groups[g].bars[b];
      if (!(bar.value > 0.0)) continue;  // nothing measured there: an empty place
      const double h = bar.value * to_px, x = x0 + bar_w * static_cast<double>(b);
      out += "<rect class=\"" + escape(bar.css_class) + "\"" + attr("x", x + 1.0) + attr("y", kTop + kAreaH - h) +
             attr("width", bar_w - 2.0) + attr("height", h) + "><title>" + escape(bar.tooltip) + "</title></rect>";
      char text[32];
      std::snprintf(text, sizeof text, "%.2f", bar.value);
      out += "<text class=\"val\" text-anchor=\"middle\"" + attr("x", x + bar_w / 2.0) + attr("y", kTop + kAreaH - h - 3.0) +
             ">" + text + "</text>";
    }
    out += "<text class=\"glabel\" text-anchor=\"middle\"" + attr("x", x0 + 0.4 * group_w) +
           attr("y", kTop + kAreaH + 22.0) + ">" + escape(groups[g].label) + "</text>";
  }
  if (reference > 0.0) {
    const double y = kTop + kAreaH - reference * to_px;
    out += "<line class=\"ref\"" + attr("x1", kLeft) + attr("x2", kLeft + kAreaW) + attr("y1", y) + attr("y2", y) + "/>";
  }
  out += "<rect class=\"frame\"" + attr("x", kLeft) + attr("y", kTop) + attr("width", kAreaW) + attr("height", kAreaH) + "/>";
  return out + "</svg>\n";
}

std::string paired_bars(const std::vector<PairRow>& rows) {
  constexpr double kW = 1000.0, kLeft = 190.0, kRight = 90.0, kTop = 8.0, kRowH = 30.0;
  const double h = kTop + kRowH * static_cast<double>(rows.size()) + 26.0;
  double lo = 0.0, hi = 1.0;
  for (const PairRow& r : rows) {
    lo = std::min({lo, symlog(r.value), symlog(r.against)});
    hi = std::max({hi, symlog(r.value), symlog(r.against)});
  }
  lo = std::floor(lo);
  hi = std::ceil(hi);
  const double area_w = kW - kLeft - kRight, to_px = area_w / (hi - lo);
  auto x_of = [&](double v) { return kLeft + (symlog(v) - lo) * to_px; };
  std::string out = "<svg class=\"plot pairs\" role=\"img\" viewBox=\"0 0 " + number(kW) + " " + number(h) + "\">";
  for (double e = lo; e <= hi; e += 1.0) {  // 0, +-10^n: the symmetric log scale's decades
    const double v = e == 0.0 ? 0.0 : std::copysign(std::pow(10.0, std::abs(e)), e);
    const double x = kLeft + (e - lo) * to_px;
    out += "<line class=\"" + std::string(e == 0.0 ? "zero" : "grid") + "\"" + attr("x1", x) + attr("x2", x) +
           attr("y1", kTop - 4.0) + attr("y2", h - 22.0) + "/>";
    out += "<text class=\"tick\" text-anchor=\"middle\"" + attr("x", x) + attr("y", h - 8.0) + ">" + number(v, 6) + "</text>";
  }
  const double x0 = x_of(0.0);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PairRow& r = rows[i];
    const double y = kTop + kRowH * static_cast<double>(i), xv = x_of(r.value), xa = x_of(r.against);
    out += "<text class=\"rlabel\" text-anchor=\"end\"" + attr("x", kLeft - 8.0) + attr("y", y + 15.0) + ">" +
           escape(r.label) + "</text>";
    out += "<rect class=\"" + escape(r.css_class) + "\"" + attr("x", std::min(x0, xv)) + attr("y", y + 3.0) +
           attr("width", std::abs(xv - x0)) + attr("height", 13.0) + "><title>" + number(r.value, 5) + "</title></rect>";
    out += "<rect class=\"penalty\"" + attr("x", std::min(x0, xa)) + attr("y", y + 18.0) + attr("width", std::abs(xa - x0)) +
           attr("height", 6.0) + "><title>" + number(r.against, 5) + "</title></rect>";
    char text[64];
    std::snprintf(text, sizeof text, "%+.1f / %.1f", r.value, r.against);
    out += "<text class=\"val\"" + attr("x", std::max({xv, xa, x0}) + 5.0) + attr("y", y + 15.0) + ">" + text + "</text>";
  }
  return out + "</svg>\n";
}

}  // namespace sinu::diagnose::svg
