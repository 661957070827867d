#pragma once
// The baseline replay's innovations over time, kept in memory for the plots
// of report.html: each component of each aiding source's innovation with the
// sigma the filter predicted for it, and the flight phase over time.
#include <array>
#include <vector>

#include "firmware/host/diagnose/innovation_stats.hpp"

namespace sinu::diagnose {

inline constexpr std::size_t kMaxInnovationRows = 3;

/// Component names per aiding source, as innovations.csv's `component` column.
inline constexpr std::array<std::array<const char*, kMaxInnovationRows>, est::kAidingSourceCount>
    kInnovationComponentNames = {{{"north", "east", "down"},
                                  {"north", "east", ""},
                                  {"x", "y", "z"},
                                  {"north", "east", "down"},
                                  {"lateral", "vertical", ""}}};
/// Unit of each aiding source's innovation.
inline constexpr std::array<const char*, est::kAidingSourceCount> kInnovationUnits = {"m", "m/s", "uT", "m/s", "m/s"};

struct InnovationPoint {
  double t_s = 0.0;
  float innovation = 0.0f, sigma = 0.0f;  // in the source's unit
  bool accepted = false;
};

struct PhaseSpan {
  double start_s = 0.0, end_s = 0.0;
  Phase phase = Phase::Straight;
};

struct InnovationSeries {
  // [source][component], in time order; components without a predicted sigma are left out.
  std::array<std::array<std::vector<InnovationPoint>, kMaxInnovationRows>, est::kAidingSourceCount> points{};
  std::vector<PhaseSpan> phases;         // consecutive, over the solutions' time
  double t_first_s = 0.0, t_last_s = 0.0;  // the first and last solution or innovation
  bool has_source(std::size_t source) const;
};

/// Records every innovation and the phase of every solution of one replay.
class InnovationSeriesListener final : public replay::ReplayListener {
 public:
  void on_nav(const est::NavOutput& out) override;
  void on_innovation(const est::InnovationRecord& rec) override;
  InnovationSeries take() { return std::move(series_); }

 private:
  void extend_time(double t_s);
  InnovationSeries series_;
  PhaseTracker phases_;
  bool have_time_ = false;
};

}  // namespace sinu::diagnose
