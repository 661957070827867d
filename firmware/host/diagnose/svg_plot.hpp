#pragma once
// Inline SVG plots for report.html, written as text: time series with bands
// (reduced to a min/max pair per pixel column, so a long flight stays small)
// and bar charts. No scripts and no external references; report.html's small
// script only moves the time axis (zoom, pan) of what is drawn here.
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sinu::diagnose::svg {

/// Text for HTML content and attribute values: & < > " ' escaped.
std::string escape(std::string_view text);
/// A number for labels and coordinates: `significant` digits, no trailing zeros.
std::string number(double v, int significant = 4);

/// Round tick values inside [lo, hi], about `count` of them: steps of 1, 2 or
/// 5 x 10^n (the same rule as report.html's script uses when zooming).
std::vector<double> nice_ticks(double lo, double hi, int count);

struct Sample {
  double t_s = 0.0, y = 0.0;
};

/// At most two samples per column of [t0_s, t1_s] split into `columns`: the
/// column's smallest and largest y, in the order they occurred (the shape a
/// pixel column shows). The samples themselves when there are few enough.
std::vector<Sample> min_max_per_column(std::span<const Sample> samples, double t0_s, double t1_s, int columns);
/// One sample per column: the mean time and value of its samples (a slowly varying sigma).
std::vector<Sample> mean_per_column(std::span<const Sample> samples, double t0_s, double t1_s, int columns);

/// Path data ("M t,y t,y ...") in data coordinates (x: seconds after t0_s,
/// y: -value, SVG's y points down), values clipped to +-clip, a new subpath
/// after each gap longer than gap_s.
std::string line_path(std::span<const Sample> samples, double t0_s, double gap_s, double clip);
/// A dot at each sample (zero-length segments drawn with round caps); same coordinates as line_path.
std::string dot_path(std::span<const Sample> samples, double t0_s, double clip);
/// Closed path data of the band +-factor x sigma around zero, one subpath per
/// stretch without gaps; same coordinates as line_path.
std::string band_path(std::span<const Sample> sigma, double t0_s, double gap_s, double factor, double clip);

/// A time-series plot: the value axis fixed at +-y_max, the time axis
/// [0, span_s] (seconds after the flight's first solution) zoomable by the
/// page's script (the nested <svg class="zx"> viewBoxes and the <g class="xt"> ticks).
struct TimePlot {
  std::string title;      // above the plot, left: "north [m]"
  std::string note;       // above the plot, right (may be empty)
  double span_s = 1.0;
  double y_max = 1.0;
  std::string shading;    // elements in (seconds, 0..1) coordinates, under the data
  std::string data;       // elements in line_path's coordinates
};
std::string time_plot(const TimePlot& p);

/// A vertical bar chart in groups (one group per source, one bar per phase).
struct Bar {
  double value = 0.0;
  std::string css_class;  // its colour
  std::string tooltip;
};
struct BarGroup {
  std::string label;
  std::vector<Bar> bars;
};
/// `reference`: a dashed line at that value (NIS 1), 0 for none.
std::string grouped_bars(const std::vector<BarGroup>& groups, const std::string& y_label, double reference);

/// Horizontal pairs of bars on a symmetric log scale (sign(v) log10(1 + |v|)):
/// per row a thick bar (`value`, coloured by css_class) and a thin dark one
/// (`against`): a likelihood gain against its penalty, for values from below
/// zero to thousands. The legend is the page's.
struct PairRow {
  std::string label;
  double value = 0.0, against = 0.0;
  std::string css_class;
};
std::string paired_bars(const std::vector<PairRow>& rows);

}  // namespace sinu::diagnose::svg
