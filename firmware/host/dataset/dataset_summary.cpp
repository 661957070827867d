#include "firmware/host/dataset/dataset_summary.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "estimator/nav/sensor_scale_check.hpp"
#include "firmware/host/dataset/csv_table.hpp"
#include "firmware/host/dataset/imu_csv.hpp"
#include "firmware/host/dataset/nmea_log.hpp"
#include "firmware/host/dataset/truth_csv.hpp"

namespace sinu::dataset {

std::string ImuSummary::units_warning() const {
  std::string w;
  const double f = mean_specific_force_m_s2(), m = mean_field_uT();
  // The replay's bounds, against gravity and the Earth's 22-67 uT (inspect
  // knows no position for the model's field).
  const est::SensorScaleCheckConfig bound;
  if (accel_rows && (f < bound.accel_min_ratio * 9.8 || f > bound.accel_max_ratio * 9.8))
    w += fmt::format("mean |f| {:.3g} is not ~9.8: ax, ay, az must be m/s^2 (in g they read 0.1x); ", f);
  if (mag_rows && (m < 22.0 / bound.mag_max_ratio || m > 67.0 * bound.mag_max_ratio))
    w += fmt::format("mean |m| {:.3g} is not the Earth's 22-67: mx, my, mz must be uT (mG read 10x, G 0.01x); ", m);
  if (!w.empty()) w.resize(w.size() - 2);
  return w;
}

namespace {

bool read_imu(const std::string& path, ImuSummary& s, Diagnostic& err) {
  CsvReader reader(kImuSchema);
  if (!reader.open(path)) return (err = reader.error()), false;
  ImuRow r;
  ReadStatus st;
  while ((st = reader.next(r.row)) == ReadStatus::Row) {
    s.time.add(r.t_s());
    s.accel_rows += r.has_accel();
    s.gyro_rows += r.has_gyro();
    s.mag_rows += r.has_mag();
    const auto norm = [](const std::array<double, 3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); };
    if (r.has_accel()) s.sum_specific_force_m_s2 += norm(r.specific_force_b_m_s2());
    if (r.has_mag()) s.sum_field_uT += norm(r.mag_b_uT());
    s.temp_rows += r.has_temp();
  }
  s.time.finish();
  if (st == ReadStatus::Error) return (err = reader.error()), false;
  if (s.time.count() == 0) return (err = Diagnostic{path, 0, 0, "no samples after the header"}), false;
  return true;
}

bool read_gps(const std::string& path, GpsSummary& s, Diagnostic& err) {
  GpsLogReader reader;
  if (!reader.open(path)) return (err = reader.error()), false;
  drivers::GpsFix fix;
  ReadStatus st;
  while ((st = reader.next(fix)) == ReadStatus::Row) {
    ++s.epochs;
    if (fix.has_position()) {
      s.fixes.add(fix.arrival_s);
      s.fixes_with_sigma += fix.has_gst;
      s.fixes_without_height += fix.horizontal_only();
    }
  }
  s.fixes.finish();
  if (st == ReadStatus::Error) return (err = reader.error()), false;
  s.late_sentences = reader.late_sentences();
  s.lines = reader.log().lines();
  s.skipped_lines = reader.log().skipped_lines();
  s.sentences = reader.counters();
  s.first_corrupt = reader.log().skipped_lines() > 0 ? reader.log().first_skipped() : reader.first_corrupt();
  return true;
}

bool read_truth(const std::string& path, TruthSummary& s, Diagnostic& err) {
  CsvReader reader(kTruthSchema);
  if (!reader.open(path)) return (err = reader.error()), false;
  CsvRow r;
  ReadStatus st;
  while ((st = reader.next(r)) == ReadStatus::Row) {
    s.time.add(r.t());
    s.attitude_rows += r.has(truth_col::roll) && r.has(truth_col::pitch) && r.has(truth_col::yaw);
  }
  s.time.finish();
  if (st == ReadStatus::Error) return (err = reader.error()), false;
  return true;
}

std::string rate_line(const char* what, const RateTracker& r, const char* unit) {
  std::string out = fmt::format("  {:<9} {:>9} {}  {:.3f} .. {:.3f} s  ({:.1f} s)  {:.2f} Hz", what, r.count(), unit,
                                r.first_s(), r.last_s(), r.duration_s(), r.nominal_rate_hz());
  if (r.gaps() > 0)
    out += fmt::format("  {} gaps, longest {:.3f} s at t={:.3f}", r.gaps(), r.longest_gap_s(), r.longest_gap_at_s());
  else
    out += "  no gaps";
  return out + "\n";
}

nlohmann::json rate_json(const RateTracker& r) {
  return {{"count", r.count()},        {"t_first", r.first_s()},  {"t_last", r.last_s()},
          {"duration_s", r.duration_s()}, {"rate_hz", r.nominal_rate_hz()}, {"gaps", r.gaps()},
          {"longest_gap_s", r.longest_gap_s()}, {"longest_gap_at", r.longest_gap_at_s()}};
}

}  // namespace

bool summarize_dataset(const DatasetPaths& paths, DatasetSummary& out, Diagnostic& err) {
  out = DatasetSummary{};
  out.dir = paths.dir.string();
  if (!std::filesystem::is_directory(paths.dir)) {
    err = Diagnostic{out.dir, 0, 0, "not a directory"};
    return false;
  }
  if (!std::filesystem::exists(paths.imu())) {
    err = Diagnostic{paths.imu(), 0, 0, "missing: every dataset needs imu.csv"};
    return false;
  }
  if (!read_imu(paths.imu(), out.imu, err)) return false;
  if (paths.has_gps() && !read_gps(paths.gps(), out.gps.emplace(), err)) return false;
  if (paths.has_truth() && !read_truth(paths.truth(), out.truth.emplace(), err)) return false;
  if (paths.has_meta() && !read_meta(paths.meta(), out.meta.emplace(), err)) return false;
  return true;
}

std::string format_summary(const DatasetSummary& s) {
  std::string o = fmt::format("dataset {}\n", s.dir);
  o += rate_line("imu.csv", s.imu.time, "rows");
  o += fmt::format("            accel {} gyro {} mag {} temp {} rows\n", s.imu.accel_rows, s.imu.gyro_rows,
                   s.imu.mag_rows, s.imu.temp_rows);
  o += fmt::format("            mean |f| {:.4g} m/s^2, mean |m| {}\n", s.imu.mean_specific_force_m_s2(),
                   s.imu.mag_rows ? fmt::format("{:.4g} uT", s.imu.mean_field_uT()) : std::string("-"));
  if (const std::string w = s.imu.units_warning(); !w.empty()) o += "            UNITS? " + w + "\n";
  if (s.gps) {
    const auto& g = *s.gps;
    o += fmt::format("  gps.nmea  {:>9} lines  {} sentences decoded, {} ignored, {} corrupt", g.lines,
                     g.sentences.good, g.sentences.ignored, g.sentences.corrupt() + g.skipped_lines);
    o += fmt::format(" (checksum {}, no checksum {}, too long {}, framing {}, bad field {}, bad line {})\n",
                     g.sentences.bad_checksum, g.sentences.missing_checksum, g.sentences.too_long,
                     g.sentences.bad_framing, g.sentences.malformed_field, g.skipped_lines);
    o += fmt::format("            {} epochs, {} with a position fix ({} with GST sigmas)", g.epochs, g.fixes.count(),
                     g.fixes_with_sigma);
    if (g.fixes_without_height)
      o += fmt::format("; {} without a height (no GGA: replay cannot start from them)", g.fixes_without_height);
    if (g.late_sentences) o += fmt::format("; {} late or repeated-time sentences dropped", g.late_sentences);
    o += "\n";
    if (g.fixes.count() > 0) o += rate_line("fixes", g.fixes, "fixes");
    if (!g.first_corrupt.message.empty()) o += "            first corrupt: " + g.first_corrupt.to_string() + "\n";
  } else {
    o += "  gps.nmea  absent\n";
  }
  if (s.truth) {
    o += rate_line("truth.csv", s.truth->time, "rows");
    o += fmt::format("            attitude in {} rows\n", s.truth->attitude_rows);
  } else {
    o += "  truth.csv absent\n";
  }
  if (s.meta) {
    o += fmt::format("  meta.json imu_rate_hz {}  gps_rate_hz {}\n",
                     s.meta->imu_rate_hz ? fmt::format("{:g}", *s.meta->imu_rate_hz) : "-",
                     s.meta->gps_rate_hz ? fmt::format("{:g}", *s.meta->gps_rate_hz) : "-");
  } else {
    o += "  meta.json absent\n";
  }
  return o;
}

std::string format_summary_json(const DatasetSummary& s) {
  nlohmann::json j;
  j["dir"] = s.dir;
  j["imu"] = {{"time", rate_json(s.imu.time)},
              {"accel_rows", s.imu.accel_rows},
              {"gyro_rows", s.imu.gyro_rows},
              {"mag_rows", s.imu.mag_rows},
              {"temp_rows", s.imu.temp_rows},
              {"mean_specific_force_m_s2", s.imu.mean_specific_force_m_s2()},
              {"mean_field_uT", s.imu.mag_rows ? nlohmann::json(s.imu.mean_field_uT()) : nlohmann::json(nullptr)},
              {"units_warning", s.imu.units_warning()}};
  if (s.gps) {
    const auto& g = *s.gps;
    j["gps"] = {{"lines", g.lines},
                {"sentences_good", g.sentences.good},
                {"sentences_ignored", g.sentences.ignored},
                {"corrupt", g.sentences.corrupt() + g.skipped_lines},
                {"bad_checksum", g.sentences.bad_checksum},
                {"missing_checksum", g.sentences.missing_checksum},
                {"too_long", g.sentences.too_long},
                {"bad_framing", g.sentences.bad_framing},
                {"malformed_field", g.sentences.malformed_field},
                {"skipped_lines", g.skipped_lines},
                {"epochs", g.epochs},
                {"fixes", rate_json(g.fixes)},
                {"fixes_with_sigma", g.fixes_with_sigma},
                {"fixes_without_height", g.fixes_without_height},
                {"late_sentences", g.late_sentences}};
  }
  if (s.truth) j["truth"] = {{"time", rate_json(s.truth->time)}, {"attitude_rows", s.truth->attitude_rows}};
  if (s.meta) j["meta"] = s.meta->object;
  return j.dump(1) + "\n";
}

}  // namespace sinu::dataset
