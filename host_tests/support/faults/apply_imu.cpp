// The imu.csv faults: clipping, gap, missing magnetometer, a bias shift; and the reboot
// (DropLeadingSeconds), which cuts every file at the same instant.
#include "host_tests/support/faults/apply.hpp"
#include "host_tests/support/faults/imu_clip.hpp"

#include <cstdio>
#include <cstdlib>

namespace sinu::test::faults {

namespace {

constexpr std::size_t kMagX = 7;  // imu.csv: t,ax,ay,az,gx,gy,gz,mx,my,mz,temp

}  // namespace

FaultEffect apply(const ImuClip& f, DatasetText& d) {
  FaultEffect e;
  for (std::size_t i = 1; i < d.imu.size(); ++i) {
    auto& line = d.imu[i];
    const auto t = leading_number(line.text);
    if (!t || !in_window(*t, f.start_s, f.duration_s)) continue;
    auto fields = split_fields(line.text);
    if (!clip_imu_row(fields, *t, f)) continue;
    line.text = join_fields(fields);
    ++e.changed;
  }
  return e;
}

FaultEffect apply(const ImuGap& f, DatasetText& d) {
  return {0, remove_timed_lines(d.imu, [&](double t) { return in_window(t, f.start_s, f.duration_s); })};
}

FaultEffect apply(const ImuDropMagFirstRows& f, DatasetText& d) {
  FaultEffect e;
  for (std::size_t i = 1; i < d.imu.size() && i <= f.count; ++i) {
    auto fields = split_fields(d.imu[i].text);
    if (fields.size() < kMagX + 3) continue;
    bool changed = false;
    for (std::size_t c = kMagX; c < kMagX + 3; ++c) {
      changed = changed || !fields[c].empty();
      fields[c].clear();
    }
    if (!changed) continue;
    d.imu[i].text = join_fields(fields);
    ++e.changed;
  }
  return e;
}

FaultEffect apply(const ImuTimeGlitch& f, DatasetText& d) {
  for (std::size_t i = 2; i < d.imu.size(); ++i) {
    const auto t = leading_number(d.imu[i].text);
    const auto t_before = leading_number(d.imu[i - 1].text);
    if (!t || !t_before || *t < f.at_s) continue;
    auto fields = split_fields(d.imu[i].text);
    const double glitch = f.kind == TimeGlitchKind::Repeat ? *t_before : *t_before - f.step_back_s;
    char text[64];
    std::snprintf(text, sizeof text, "%.6f", glitch);
    fields[0] = text;
    d.imu[i].text = join_fields(fields);
    return {1, 0};
  }
  return {};
}

FaultEffect apply(const ImuNonFinite& f, DatasetText& d) {
  FaultEffect e;
  for (std::size_t i = 1; i < d.imu.size(); ++i) {
    const auto t = leading_number(d.imu[i].text);
    if (!t || !in_window(*t, f.start_s, f.duration_s)) continue;
    auto fields = split_fields(d.imu[i].text);
    if (fields.size() < 5) continue;
    fields[1] = "nan";  // ax
    fields[4] = "nan";  // gx
    d.imu[i].text = join_fields(fields);
    ++e.changed;
  }
  return e;
}

FaultEffect apply(const ImuBiasShift& f, DatasetText& d) {
  FaultEffect e;
  for (std::size_t i = 1; i < d.imu.size(); ++i) {
    const auto t = leading_number(d.imu[i].text);
    if (!t || *t < f.start_s) continue;
    auto fields = split_fields(d.imu[i].text);
    if (fields.size() <= f.column || fields[f.column].empty()) continue;  // no sample: stays empty
    char text[64];
    std::snprintf(text, sizeof text, "%.9g", std::strtod(fields[f.column].c_str(), nullptr) + f.delta);
    fields[f.column] = text;
    d.imu[i].text = join_fields(fields);
    ++e.changed;
  }
  return e;
}

namespace {

/// Every file cut at t0 + seconds (t0 the first imu.csv time): the lines before
/// the cut removed (keep_before false) or those from it on (true).
FaultEffect cut_every_file(double seconds, bool keep_before, DatasetText& d) {
  std::optional<double> t0;
  for (std::size_t i = 1; i < d.imu.size() && !t0; ++i) t0 = leading_number(d.imu[i].text);
  if (!t0) return {};
  const double cut = *t0 + seconds;
  auto drop = [&](double t) { return keep_before ? t >= cut : t < cut; };
  FaultEffect e;
  e.removed += remove_timed_lines(d.imu, drop);  // the header has no readable time: it stays
  if (d.gps) e.removed += remove_timed_lines(*d.gps, drop);
  if (d.truth) e.removed += remove_timed_lines(*d.truth, drop);
  return e;
}

}  // namespace

FaultEffect apply(const DropLeadingSeconds& f, DatasetText& d) { return cut_every_file(f.seconds, false, d); }
FaultEffect apply(const KeepLeadingSeconds& f, DatasetText& d) { return cut_every_file(f.seconds, true, d); }

}  // namespace sinu::test::faults
