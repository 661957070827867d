#include "firmware/host/diagnose/innovation_series.hpp"

#include <algorithm>

namespace sinu::diagnose {

bool InnovationSeries::has_source(std::size_t source) const {
  return std::any_of(points[source].begin(), points[source].end(), [](const auto& p) { return !p.empty(); });
}

void InnovationSeriesListener::extend_time(double t_s) {
  if (!have_time_) series_.t_first_s = series_.t_last_s = t_s;
  have_time_ = true;
  series_.t_first_s = std::min(series_.t_first_s, t_s);
  series_.t_last_s = std::max(series_.t_last_s, t_s);
}

void InnovationSeriesListener::on_nav(const est::NavOutput& out) {
  const double t = out.nav.t_s;
  extend_time(t);
  const Phase phase = phases_.on_nav(out);
  std::vector<PhaseSpan>& spans = series_.phases;
  if (!spans.empty() && spans.back().phase == phase) {
    spans.back().end_s = t;
    return;
  }
  if (!spans.empty()) spans.back().end_s = t;
  spans.push_back({t, t, phase});
}

void InnovationSeriesListener::on_innovation(const est::InnovationRecord& rec) {
  const auto k = static_cast<std::size_t>(rec.source);
  if (k >= est::kAidingSourceCount) return;
  extend_time(rec.t_s);
  for (Eigen::Index i = 0; i < rec.result.rows && i < static_cast<Eigen::Index>(kMaxInnovationRows); ++i) {
    const double s = rec.result.innovation_sigma(i);
    if (!(s > 0.0)) continue;  // no predicted sigma: nothing to plot against
    series_.points[k][static_cast<std::size_t>(i)].push_back(
        {rec.t_s, static_cast<float>(rec.result.innovation(i)), static_cast<float>(s), rec.result.accepted});
  }
}

}  // namespace sinu::diagnose
