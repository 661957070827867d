#include "firmware/host/replay/replay_files.hpp"

#include "firmware/board/config/vehicle_words.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

namespace sinu::replay {

void NavCsvWriter::on_start(const est::Navigator& nav) {
  nav_ = &nav;
  opened_ = log_.open(path_, nav.filter().layout(), period_s_);
}

void NavCsvWriter::on_nav(const est::NavOutput& out) {
  if (opened_) log_.on_nav(out, nav_->filter());
}

bool NavCsvWriter::close(std::string& error) {
  if (!opened_ || !log_.close()) {
    error = path_ + (opened_ ? ": write failed (disk full?)" : ": cannot create");
    return false;
  }
  return true;
}

void InnovationCsvWriter::on_start(const est::Navigator&) {
  opened_ = out_.open(path_);
  if (opened_) out_.text("t,source,component,innovation,sigma,test_ratio,accepted\n");
}

void InnovationCsvWriter::on_innovation(const est::InnovationRecord& rec) {
  static constexpr const char* kComponents[est::kAidingSourceCount][3] = {
      {"north", "east", "down"}, {"north", "east", ""}, {"x", "y", "z"}, {"north", "east", "down"},
      {"lateral", "vertical", ""}};
  const auto src = static_cast<std::size_t>(rec.source);
  for (Eigen::Index i = 0; i < rec.result.rows; ++i) {
    out_.number(rec.t_s, 6);
    out_.comma();
    out_.text(est::kAidingSourceNames[src]);
    out_.comma();
    out_.text(kComponents[src][i]);
    out_.comma();
    out_.number(rec.result.innovation(i), 4);
    out_.comma();
    out_.number(rec.result.innovation_sigma(i), 4);
    out_.comma();
    out_.number(rec.result.test_ratio(i), 4);
    out_.comma();
    out_.text(rec.result.accepted ? "1" : "0");
    out_.end_row();
  }
}

bool InnovationCsvWriter::close(std::string& error) {
  if (!opened_ || !out_.close()) {
    error = path_ + (opened_ ? ": write failed (disk full?)" : ": cannot create");
    return false;
  }
  return true;
}

nlohmann::json summary_json(const ReplayOptions& opt, const ReplayResult& r) {
  using nlohmann::json;
  const auto num = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  const board::CalibChoice& calib = opt.unit.calib;
  const est::NavCounters& c = r.counters;
  const NavMetrics& m = r.metrics;
  json sj;
  sj["dataset"] = r.dataset;
  sj["model"] = calib.kind == est::NoiseModelKind::GaussMarkov ? "gm" : "ar";
  if (calib.kind == est::NoiseModelKind::AutoRegressive)
    sj["ar"] = {{"method", calib.ar_method}, {"order", calib.ar_order}, {"rate_hz", r.ar_rate_hz}};
  sj["calib"] = opt.unit.calib_path.empty() ? json(nullptr) : json(opt.unit.calib_path);
  sj["states"] = r.states;
  sj["denoiser"] = r.denoiser;
  const VehicleOutcome& v = r.vehicle;
  json detected = nullptr;
  if (v.guess == est::VehicleGuess::Ground) detected = "ground";
  if (v.guess == est::VehicleGuess::Reverted) detected = "ground, reverted to air";
  sj["vehicle"] = {{"configured", board::vehicle_word(v.configured)},
                   {"constraints_at_end", v.ground_at_end ? "ground" : "none"},
                   {"detected", detected},
                   {"detected_at_s", v.guess != est::VehicleGuess::Undecided && !v.restored ? json(v.detected_at_s)
                                                                                            : json(nullptr)},
                   {"from_state_file", v.restored},
                   {"evidence", {{"moving_s", v.moving_s}, {"lateral_rms_m_s", v.lateral_rms_m_s},
                                 {"vertical_rms_m_s", v.vertical_rms_m_s},
                                 {"bank_per_g", std::isfinite(v.bank_per_g) ? json(v.bank_per_g) : json(nullptr)}}},
                   {"unit_on_vehicle", {{"found", v.on_bracket},
                                        {"roll_deg", v.on_bracket ? json(v.unit_roll_deg) : json(nullptr)},
                                        {"pitch_deg", v.on_bracket ? json(v.unit_pitch_deg) : json(nullptr)},
                                        {"yaw_deg", v.on_bracket ? json(v.unit_yaw_deg) : json(nullptr)}}}};
  json eff = json::array();
  for (const EffectEstimate& e : r.effects) {
    eff.push_back({{"name", est::kEffectNames[static_cast<std::size_t>(e.effect)]}, {"estimate", e.estimate}, {"sigma", e.sigma}});
  }
  sj["effects"] = eff;
  sj["imu_samples"] = r.imu_samples;
  sj["duration_s"] = r.duration_s;
  sj["aligned"] = r.aligned;
  sj["note"] = r.note;  // what the user must know ("" if nothing): dropped rows, the state file
  sj["aligned_at_s"] = r.aligned ? json(r.aligned_at_s) : json(nullptr);
  constexpr double kDeg = 180.0 / std::numbers::pi;
  if (r.aligned) {
    const est::AlignmentResult& a = r.alignment;
    sj["alignment"] = {{"at_rest", a.at_rest},
                       {"heading_from", est::heading_source_name(a.heading_source)},
                       {"field_corrected_by_saved_iron", a.field_corrected_by_saved_iron},
                       {"saved_iron_refused", a.saved_iron_refused},
                       {"saved_biases", a.saved_biases == est::SavedBiases::Kept    ? json("kept")
                                        : a.saved_biases == est::SavedBiases::Moved ? json("moved")
                                                                                    : json(nullptr)},
                       {"declination_deg", num(a.declination_rad * kDeg)},
                       {"field_over_model", num(a.field_ratio)},
                       {"dip_minus_model_deg", num(a.dip_difference_rad * kDeg)},
                       {"course_turned_deg", num(a.course_turn_rad * kDeg)},
                       {"course_turned_at_s", num(a.course_turn_t_s)}};
  } else {
    // Why there is no solution, and the field check that refused the magnetometer's heading (null: none).
    sj["not_aligned"] = {{"reason", r.not_aligned_reason()},
                         {"field_over_model", num(r.alignment.field_ratio)},
                         {"dip_minus_model_deg", num(r.alignment.dip_difference_rad * kDeg)},
                         {"saved_iron_refused", r.alignment.saved_iron_refused}};
  }
  // The units check (estimator/nav/sensor_scale_check.hpp): null where nothing was judged.
  sj["sensor_units"] = {{"specific_force_over_gravity", num(r.scale.specific_force_over_gravity)},
                        {"expected_over_gravity", num(r.scale.expected_over_gravity)},
                        {"accel_refused", r.scale.accel_refused},
                        {"gyro_std_at_rest_rad_s", num(r.scale.gyro_std_at_rest_rad_s)},
                        {"gyro_refused", r.scale.gyro_refused},
                        {"field_over_model", num(r.scale.field_over_model)},
                        {"mag_refused_samples", r.scale.mag_refused_samples},
                        {"mag_refused", r.mag_refused_reason()}};
  sj["rmse"] = {{"pos_h_m", num(r.rmse_pos_h_m())}, {"pos_v_m", num(r.rmse_pos_v_m())}, {"vel_m_s", num(r.rmse_vel_m_s())},
                {"att_deg", num(r.rmse_att_deg())}, {"truth_points", m.compared}};
  json outs = json::array();
  for (const OutageDrift& o : m.outages) {
    outs.push_back({{"start", o.window.start_s}, {"duration", o.window.duration_s},
                    {"max_drift_h_m", o.points ? json(o.max_drift_h_m) : json(nullptr)},
                    {"fixes_withheld", o.fixes_withheld}});
  }
  sj["outages"] = outs;
  sj["outage_max_drift_h_rms_m"] = num(r.outage_drift_rms_m());
  json nis;
  for (std::size_t i = 0; i < est::kAidingSourceCount; ++i) {
    const ChiStats& s = m.nis[i];
    nis[est::kAidingSourceNames[i]] = {{"count", s.count}, {"mean", s.mean()}, {"inside_95", s.inside_fraction()}};
  }
  sj["nis"] = nis;
  sj["nees"] = {{"dof", m.nees_dof}, {"count", m.nees.count}, {"mean", m.nees.mean()},
                {"inside_95", m.nees.inside_fraction()},
                {"after_settling", {{"from_s", NavMetrics::kSettleS}, {"mean", m.nees_settled.mean()},
                                    {"inside_95", m.nees_settled.inside_fraction()}}}};
  json rejected = json::object(), accepted = json::object();
  for (std::size_t i = 0; i < est::kAidingSourceCount; ++i) {
    rejected[est::kAidingSourceNames[i]] = c.rejected[i];
    accepted[est::kAidingSourceNames[i]] = c.accepted[i];
  }
  sj["rejected"] = rejected;
  sj["accepted"] = accepted;
  sj["gnss"] = {{"epochs", r.gnss.epochs},
                {"used", r.gnss.used},
                {"without_height", r.gnss.without_height},
                {"without_height_fused", c.horizontal_fixes},
                {"course_held", c.course_held},
                {"dropped_outage", r.gnss.dropped_outage},
                {"dropped_period", r.gnss.dropped_period}, {"late", c.gnss_late}, {"overflow", c.gnss_overflow}};
  sj["corrupt_sentences"] = r.source.corrupt_sentences;
  sj["imu"] = {{"incomplete_rows", r.source.incomplete_rows}, {"rows_folded", r.source.rows_folded},
               {"accel_interpolated_samples", r.source.accel_interpolated},
               {"accel_held_samples", r.source.accel_held}, {"time_anomalies", r.source.time_anomalies},
               {"non_finite_rows", r.source.non_finite_rows},
               {"first_anomaly", r.source.first_anomaly.empty() ? json(nullptr) : json(r.source.first_anomaly)},
               {"non_increasing", c.imu_non_increasing}, {"gaps", c.imu_gaps}, {"gap_total_s", c.imu_gap_total_s},
               {"longest_gap_s", c.imu_longest_gap_s}, {"invalid", c.imu_invalid},
               {"clipped_samples", c.imu_clipped_samples}};
  // Health: whether this solution can be trusted, before any figure of merit.
  sj["health"] = {{"status", health_status_name(r.health())},
                  {"lost_s", c.lost_total_s},
                  {"first_lost_t", c.lost_total_s > 0.0 ? json(c.first_lost_t_s) : json(nullptr)},
                  {"resets",
                   {{"position", c.position_resets},
                    {"velocity", c.velocity_resets},
                    {"yaw", c.yaw_resets},
                    {"vertical_velocity", c.vertical_resets}}},
                  {"magnetometer_reanchors", c.mag_reanchors},
                  {"gyro_bias_releases", c.gyro_bias_releases},
                  {"position_inflations", c.position_inflations},
                  {"gnss_bias_holds", c.gnss_bias_holds},
                  {"first_reset_t", c.resets() ? json(c.first_reset_t_s) : json(nullptr)},
                  {"gnss_timeouts", c.gnss_timeouts},
                  {"gnss_timeout_s", c.gnss_timeout_total_s}};
  sj["noise"] = {{"gnss_velocity_sigma_m_s", r.gnss_velocity_sigma_m_s},
                 {"gnss_velocity_learnt", opt.unit.adapt_velocity_noise},
                 {"magnetometer_sigma_uT", r.mag_sigma_uT},
                 {"magnetometer_learnt", opt.unit.adapt_mag_noise},
                 {"gnss_position_scale_learnt", opt.unit.adapt_position_scale},
                 {"gnss_position_scale_h", r.gnss_position_scale.x()},
                 {"gnss_position_scale_v", r.gnss_position_scale.y()},
                 {"gnss_white_scale_h", r.gnss_white_scale.x()},
                 {"gnss_white_scale_v", r.gnss_white_scale.y()}};
  sj["gnss_only_rmse"] = {{"pos_h_m", num(r.gnss_rmse_pos_h_m())}, {"pos_v_m", num(r.gnss_rmse_pos_v_m())},
                          {"fixes", m.gnss_compared}, {"truth_is_gnss_input", r.truth_is_gnss_input()},
                          {"latency_s", r.configured_gps_latency_s + r.gnss_latency_shift_s},
                          {"latency_shift_s", r.gnss_latency_shift_s},
                          {"pos_h_m_at_configured_latency", num(r.gnss_rmse_at_configured_pos_h_m())}};
  json sens = json::object();
  static constexpr const char* kAxes[] = {"ax", "ay", "az", "gx", "gy", "gz"};
  for (std::size_t a = 0; a < est::kSensorAxes; ++a) {
    sens[kAxes[a]] = {{"estimate", r.sensor_error[a]}, {"sigma", r.sensor_error_sigma[a]}};
  }
  sj["sensor_errors_final"] = sens;
  return sj;
}

bool replay_to_folder(const ReplayOptions& opt, const std::string& out_dir, double nav_rate_hz, ReplayResult& result,
                      std::string& error, std::span<ReplayListener* const> extra, bool warn) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  const fs::path out(out_dir);
  // Fail before the run, not after it, when the folder is not writable.
  if (std::FILE* probe = std::fopen((out / "summary.json").string().c_str(), "wb")) {
    std::fclose(probe);
  } else {
    error = out_dir + ": cannot create nav.csv / innovations.csv / summary.json";
    return false;
  }
  NavCsvWriter nav((out / "nav.csv").string(), nav_rate_hz > 0.0 ? 1.0 / nav_rate_hz : 0.0);
  InnovationCsvWriter innov((out / "innovations.csv").string());
  std::vector<ReplayListener*> listeners = {&nav, &innov};
  listeners.insert(listeners.end(), extra.begin(), extra.end());
  if (!run_replay(opt, listeners, result, error, warn)) return false;
  if (!nav.close(error) || !innov.close(error)) return false;
  std::ofstream so(out / "summary.json");
  so << summary_json(opt, result).dump(2) << "\n";
  if (!so) {
    error = out_dir + "/summary.json: write failed";
    return false;
  }
  return true;
}

}  // namespace sinu::replay
