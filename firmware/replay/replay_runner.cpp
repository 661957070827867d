#include "firmware/replay/replay_runner.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "estimator/ins/rotation.hpp"
#include "estimator/prefilter/wavelet_prefilter.hpp"
#include "firmware/dataset/truth_csv.hpp"
#include "firmware/replay/nav_metrics.hpp"
#include "firmware/replay/replay_source.hpp"
#include "firmware/replay/text_sink.hpp"

namespace sinu::replay {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr double kDegToRad = std::numbers::pi / 180.0;

bool truth_point(const io::CsvRow& r, TruthPoint& p) {
  using namespace io::truth_col;
  if (!r.has(lat) || !r.has(lon) || !r.has(h)) return false;
  p.t_s = r.t();
  p.lat_rad = r.value[lat] * kDegToRad;
  p.lon_rad = r.value[lon] * kDegToRad;
  p.h_m = r.value[h];
  p.has_vel = r.has(vn) && r.has(ve) && r.has(vd);
  if (p.has_vel) p.v_n = {r.value[vn], r.value[ve], r.value[vd]};
  p.has_att = r.has(roll) && r.has(pitch) && r.has(yaw);
  if (p.has_att) p.q_nb = est::quat_from_euler(r.value[roll] * kDegToRad, r.value[pitch] * kDegToRad, r.value[yaw] * kDegToRad);
  return true;
}

/// Writes nav.csv / innovations.csv rows and feeds the truth comparison.
class ReplayObserver final : public est::NavObserver {
 public:
  ReplayObserver(const est::Navigator& nav, NavMetrics& metrics, TextSink& nav_out, TextSink& innov_out,
                 io::CsvReader* truth, double nav_period_s)
      : nav_(nav), metrics_(metrics), nav_out_(nav_out), innov_out_(innov_out), truth_(truth), period_(nav_period_s) {
    advance_truth();
  }

  void on_nav(const est::NavOutput& o) override {
    if (std::isnan(first_t_)) first_t_ = o.nav.t_s;
    compare_with_truth(o);
    prev_ = o;
    have_prev_ = true;
    flags_ |= o.flags;  // events between two rows are kept
    for (std::size_t i = 0; i < est::kAidingSourceCount; ++i) test_ratio_[i] = std::max(test_ratio_[i], o.test_ratio[i]);
    warn(o);
    if (o.nav.t_s + 1e-9 >= next_write_t_) {
      write_nav(o);
      flags_ = 0;
      test_ratio_.fill(0.0);
      next_write_t_ = period_ > 0.0 ? std::floor(o.nav.t_s / period_ + 1.0 + 1e-9) * period_ : o.nav.t_s;
    }
  }

  void on_innovation(const est::InnovationRecord& rec) override {
    metrics_.add_innovation(rec);
    static constexpr const char* kComponents[est::kAidingSourceCount][3] = {
        {"north", "east", "down"}, {"north", "east", ""}, {"x", "y", "z"}, {"north", "east", "down"},
        {"lateral", "vertical", ""}};
    const auto src = static_cast<std::size_t>(rec.source);
    for (Eigen::Index i = 0; i < rec.result.rows; ++i) {
      innov_out_.number(rec.t_s, 6);
      innov_out_.comma();
      innov_out_.text(est::kAidingSourceNames[src]);
      innov_out_.comma();
      innov_out_.text(kComponents[src][i]);
      innov_out_.comma();
      innov_out_.number(rec.result.innovation(i), 4);
      innov_out_.comma();
      innov_out_.number(rec.result.innovation_sigma(i), 4);
      innov_out_.comma();
      innov_out_.number(rec.result.test_ratio(i), 4);
      innov_out_.comma();
      innov_out_.text(rec.result.accepted ? "1" : "0");
      innov_out_.end_row();
    }
  }

  double first_t() const { return first_t_; }
  std::uint32_t last_flags() const { return prev_.flags; }

 private:
  /// One line on stderr when the solution is reset or lost (the first few).
  void warn(const est::NavOutput& o) {
    namespace f = est::nav_flag;
    const bool lost = o.flags & f::kLost;
    const std::uint32_t resets = o.flags & (f::kPositionReset | f::kVelocityReset | f::kYawReset);
    if (resets && warnings_ < kMaxWarnings) {
      ++warnings_;
      std::fprintf(stderr, "sinu replay: warning: t=%.3f s: solution reset to GNSS (%s%s%s)\n", o.nav.t_s,
                   (resets & f::kPositionReset) ? "position " : "", (resets & f::kVelocityReset) ? "velocity " : "",
                   (resets & f::kYawReset) ? "yaw" : "");
    }
    if (lost && !was_lost_ && warnings_ < kMaxWarnings) {
      ++warnings_;
      std::fprintf(stderr, "sinu replay: warning: t=%.3f s: solution LOST (GNSS position and velocity rejected)\n",
                   o.nav.t_s);
    }
    was_lost_ = lost;
  }
  static constexpr int kMaxWarnings = 5;

  void advance_truth() {
    have_truth_ = false;
    if (!truth_) return;
    while (truth_->next(row_) == io::ReadStatus::Row) {
      if (truth_point(row_, truth_pt_)) {
        have_truth_ = true;
        return;
      }
    }
  }

  void compare_with_truth(const est::NavOutput& o) {
    while (have_truth_ && truth_pt_.t_s <= o.nav.t_s) {
      if (have_prev_ && truth_pt_.t_s >= prev_.nav.t_s) {
        const double span = o.nav.t_s - prev_.nav.t_s;
        const double a = span > 0.0 ? (truth_pt_.t_s - prev_.nav.t_s) / span : 1.0;
        est::NavState s = o.nav;
        s.lat_rad = prev_.nav.lat_rad + a * (o.nav.lat_rad - prev_.nav.lat_rad);
        s.lon_rad = prev_.nav.lon_rad + a * (o.nav.lon_rad - prev_.nav.lon_rad);
        s.h_m = prev_.nav.h_m + a * (o.nav.h_m - prev_.nav.h_m);
        s.v_n_m_s = prev_.nav.v_n_m_s + a * (o.nav.v_n_m_s - prev_.nav.v_n_m_s);
        s.q_nb = prev_.nav.q_nb.slerp(a, o.nav.q_nb);
        metrics_.add_truth(truth_pt_, s, o.P_nav);
      }
      advance_truth();
    }
  }

  void write_nav(const est::NavOutput& o) {
    const Eigen::Vector3d eul = est::euler_from_quat(o.nav.q_nb) * kRadToDeg;
    TextSink& w = nav_out_;
    w.number(o.nav.t_s, 6);
    w.comma();
    w.number(o.nav.lat_rad * kRadToDeg, 9);
    w.comma();
    w.number(o.nav.lon_rad * kRadToDeg, 9);
    w.comma();
    w.number(o.nav.h_m, 4);
    for (Eigen::Index i = 0; i < 3; ++i) {
      w.comma();
      w.number(o.nav.v_n_m_s(i), 4);
    }
    for (Eigen::Index i = 0; i < 3; ++i) {
      w.comma();
      w.number(eul(i), 6);
    }
    for (Eigen::Index i = 0; i < 9; ++i) {
      w.comma();
      w.number(std::sqrt(o.P_nav(i, i)) * (i >= 6 ? kRadToDeg : 1.0), 6);
    }
    for (std::size_t a = 0; a < est::kSensorAxes; ++a) {
      w.comma();
      w.number(o.sensor_error[a], 9);
    }
    for (std::size_t a = 0; a < est::kSensorAxes; ++a) {
      w.comma();
      w.number(o.sensor_error_sigma[a], 9);
    }
    w.comma();
    w.number(static_cast<double>(flags_), 0);
    for (std::size_t i = 0; i < est::kAidingSourceCount; ++i) {
      w.comma();
      w.number(test_ratio_[i], 4);
    }
    const est::ErrorStateFilter& f = nav_.filter();
    for (std::size_t e = 0; e < est::kEffectCount; ++e) {
      const auto eff = static_cast<est::Effect>(e);
      if (!f.layout().carries(eff)) continue;
      for (Eigen::Index i = 0; i < est::kEffectDims[e]; ++i) {
        w.comma();  // a reserved effect not yet switched on: empty fields ("unknown")
        if (f.layout().has(eff)) w.number(f.effect(eff, i), 9);
        w.comma();
        if (f.layout().has(eff)) w.number(f.effect_sigma(eff, i), 9);
      }
    }
    w.end_row();
  }

  const est::Navigator& nav_;
  NavMetrics& metrics_;
  TextSink& nav_out_;
  TextSink& innov_out_;
  io::CsvReader* truth_;
  double period_;
  io::CsvRow row_;
  TruthPoint truth_pt_;
  bool have_truth_ = false;
  est::NavOutput prev_;
  bool have_prev_ = false;
  double next_write_t_ = -1e300;
  double first_t_ = NAN;
  std::uint32_t flags_ = 0;
  std::array<double, est::kAidingSourceCount> test_ratio_{};
  int warnings_ = 0;
  bool was_lost_ = false;
};

std::string nav_header(const est::StateLayout& layout) {
  std::string h = "t,lat,lon,h,vn,ve,vd,roll,pitch,yaw,sigma_pn_m,sigma_pe_m,sigma_pd_m,sigma_vn,sigma_ve,sigma_vd,"
                  "sigma_att_n_deg,sigma_att_e_deg,sigma_att_d_deg,"
                  "err_ax,err_ay,err_az,err_gx,err_gy,err_gz,sigma_err_ax,sigma_err_ay,sigma_err_az,sigma_err_gx,"
                  "sigma_err_gy,sigma_err_gz,flags";
  for (const char* src : est::kAidingSourceNames) h += std::string(",test_ratio_") + src;
  for (std::size_t e = 0; e < est::kEffectCount; ++e) {
    if (!layout.carries(static_cast<est::Effect>(e))) continue;
    for (Eigen::Index i = 0; i < est::kEffectDims[e]; ++i) {
      const std::string component = est::effect_component_name(static_cast<est::Effect>(e), i);
      const std::string name = std::string(est::kEffectNames[e]) + (component.empty() ? "" : "_" + component);
      h += "," + name + ",sigma_" + name;
    }
  }
  return h + "\n";
}

/// The one path from samples to the navigator, whichever the source: GPS
/// epochs thinned by --gps-period and --outage, IMU samples as they come.
class NavigatorFeed final : public ReplayFeed {
 public:
  NavigatorFeed(est::Navigator& nav, NavMetrics& metrics, const ReplayOptions& opt)
      : nav_(nav), metrics_(metrics), opt_(opt) {}

  void on_fix(const drivers::GpsFix& f) override {
    ++epochs;
    est::GnssObservation z;
    if (!gnss_from_fix(f, opt_.sigma, z)) return;
    const double t_valid = z.arrival_s - opt_.gps_latency_s;
    for (const Outage& o : opt_.outages) {
      if (t_valid >= o.start_s && t_valid < o.start_s + o.duration_s) {
        ++dropped_outage;
        return;
      }
    }
    // Slower GPS: keep an epoch once at least a period (less 0.05 s of arrival jitter) has passed.
    if (opt_.gps_period_s > 0.0 && t_valid - last_used_t_ < opt_.gps_period_s - 0.05) {
      ++dropped_period;
      return;
    }
    last_used_t_ = t_valid;
    ++used;
    nav_.push_gnss(z);
    metrics_.add_gnss({t_valid, z.lat_rad, z.lon_rad, z.h_m});
  }

  void on_imu(const est::ImuSample& s) override {
    nav_.push_imu(s);
    if (std::isnan(t_first)) t_first = s.t_s;
    t_last = s.t_s;
    ++imu_samples;
  }

  std::uint64_t epochs = 0, used = 0, dropped_outage = 0, dropped_period = 0, imu_samples = 0;
  double t_first = NAN, t_last = NAN;

 private:
  est::Navigator& nav_;
  NavMetrics& metrics_;
  const ReplayOptions& opt_;
  double last_used_t_ = -1e300;
};

}  // namespace

bool run_replay(const ReplayOptions& opt, ReplayTotals& totals, std::string& error) {
  est::NavigatorConfig cfg;
  cfg.noise = est::SensorNoise::defaults(opt.calib.kind);
  DenoiserSpec denoiser;
  if (!opt.calib_path.empty() && !load_calib(opt.calib_path, opt.calib, cfg.noise, denoiser, error)) return false;
  cfg.noise.scale_coloured(opt.process_noise_scale);
  if (opt.denoise != "auto" && !parse_denoiser(opt.denoise, denoiser, error)) return false;
  std::unique_ptr<est::ImuPrefilter> prefilter;
  if (denoiser.wavelet) {
    prefilter = est::make_wavelet_prefilter(*est::wavelet::parse_wavelet(denoiser.name), denoiser.levels);
  }
  cfg.effects = opt.effects;
  cfg.use_mag = opt.use_mag;
  cfg.vehicle = opt.vehicle;
  cfg.mag_sigma_uT = opt.mag_sigma_uT;
  cfg.gnss_velocity_noise.enabled = opt.adapt_velocity_noise;
  cfg.mag_noise.enabled = opt.adapt_mag_noise;
  cfg.alignment.use_mag = opt.use_mag;
  if (std::isfinite(opt.mag_declination_deg)) {
    cfg.alignment.declination_known = true;
    cfg.alignment.mag_declination_rad = opt.mag_declination_deg * kDegToRad;
  }
  const std::unique_ptr<ReplaySource> source = open_replay_source(opt.in_dir, opt.imu, error);
  if (!source) return false;
  // Full scales for the clipping screen: the driver's for a recording, the user's for a dataset.
  cfg.screen.accel_range_m_s2 = opt.accel_range_m_s2;
  cfg.screen.gyro_range_rad_s = opt.gyro_range_rad_s;
  source->full_scale(cfg.screen.accel_range_m_s2, cfg.screen.gyro_range_rad_s);
  cfg.gate_sigma = opt.gate_sigma;
  cfg.gps_latency_s = opt.gps_latency_s;
  cfg.lever_arm_b_m = opt.lever_arm_b_m;
  cfg.horizon_s = std::max(0.3, opt.gps_latency_s + 0.25);

  const std::string truth_path = opt.truth_path.empty() ? source->default_truth() : opt.truth_path;
  io::CsvReader truth(io::kTruthSchema);
  const bool has_truth = !truth_path.empty();
  if (has_truth && !truth.open(truth_path)) {
    error = truth.error().to_string();
    return false;
  }
  std::error_code ec;
  std::filesystem::create_directories(opt.out_dir, ec);
  const std::filesystem::path out(opt.out_dir);
  TextSink nav_out, innov_out;
  if (!nav_out.open((out / "nav.csv").string()) || !innov_out.open((out / "innovations.csv").string())) {
    error = opt.out_dir + ": cannot create nav.csv / innovations.csv";
    return false;
  }

  auto navigator = std::make_unique<est::Navigator>();
  NavMetrics metrics;
  metrics.init(opt.outages, opt.lever_arm_b_m);
  ReplayObserver observer(*navigator, metrics, nav_out, innov_out, has_truth ? &truth : nullptr,
                          opt.nav_rate_hz > 0.0 ? 1.0 / opt.nav_rate_hz : 0.0);
  navigator->init(cfg, &observer, prefilter.get());
  nav_out.text(nav_header(navigator->filter().layout()));
  innov_out.text("t,source,component,innovation,sigma,test_ratio,accepted\n");

  NavigatorFeed feed(*navigator, metrics, opt);
  if (!source->run(feed, error)) return false;
  totals.imu_samples = feed.imu_samples;
  totals.note = source->note();
  navigator->flush();
  if (has_truth && truth.error().message.size()) {
    error = truth.error().to_string();
    return false;
  }
  const SourceCounters src = source->counters();
  if (!src.first_anomaly.empty()) {  // survived, but the user must know
    totals.note += (totals.note.empty() ? "" : "; ") + std::to_string(src.time_anomalies) +
                   " imu.csv row(s) with a time not increasing and " + std::to_string(src.non_finite_rows) +
                   " with a non-finite value were dropped; the first: " + src.first_anomaly;
  }
  const double t_first = feed.t_first, t_last = feed.t_last;
  const std::uint64_t epochs = feed.epochs, used = feed.used, dropped_outage = feed.dropped_outage,
                      dropped_period = feed.dropped_period;

  // summary.json (end of run: allocation here does not grow with the flight).
  using nlohmann::json;
  const auto& c = navigator->counters();
  const est::ErrorStateFilter& flt = navigator->filter();
  json sj;
  sj["dataset"] = opt.in_dir;
  sj["model"] = opt.calib.kind == est::NoiseModelKind::GaussMarkov ? "gm" : "ar";
  if (opt.calib.kind == est::NoiseModelKind::AutoRegressive) sj["ar"] = {{"method", opt.calib.ar_method}, {"order", opt.calib.ar_order}};
  sj["calib"] = opt.calib_path.empty() ? json(nullptr) : json(opt.calib_path);
  sj["states"] = flt.layout().dim;
  sj["denoiser"] = denoiser.wavelet ? json(denoiser.name + ":" + std::to_string(denoiser.levels)) : json("none");
  json eff = json::array();
  for (std::size_t e = 0; e < est::kEffectCount; ++e) {
    const auto ef = static_cast<est::Effect>(e);
    if (!flt.layout().has(ef)) continue;
    json vals = json::array(), sig = json::array();
    for (Eigen::Index i = 0; i < est::kEffectDims[e]; ++i) {
      vals.push_back(flt.effect(ef, i));
      sig.push_back(flt.effect_sigma(ef, i));
    }
    eff.push_back({{"name", est::kEffectNames[e]}, {"estimate", vals}, {"sigma", sig}});
  }
  sj["effects"] = eff;
  sj["imu_samples"] = totals.imu_samples;
  sj["duration_s"] = std::isnan(t_first) ? 0.0 : t_last - t_first;
  sj["aligned"] = navigator->aligned();
  sj["aligned_at_s"] = std::isnan(observer.first_t()) ? json(nullptr) : json(observer.first_t());
  const auto rms = [](double sum, std::uint64_t n) { return n ? json(std::sqrt(sum / static_cast<double>(n))) : json(nullptr); };
  sj["rmse"] = {{"pos_h_m", rms(metrics.sum_h2, metrics.compared)},
                {"pos_v_m", rms(metrics.sum_v2, metrics.compared)},
                {"vel_m_s", rms(metrics.sum_vel2, metrics.compared_vel)},
                {"att_deg", metrics.compared_att ? json(std::sqrt(metrics.sum_att2 / static_cast<double>(metrics.compared_att)) * kRadToDeg) : json(nullptr)},
                {"truth_points", metrics.compared}};
  json outs = json::array();
  double drift2 = 0.0;
  std::size_t scored = 0;  // outages with a solution and truth inside them
  for (const OutageDrift& o : metrics.outages) {
    outs.push_back({{"start", o.window.start_s}, {"duration", o.window.duration_s},
                    {"max_drift_h_m", o.points ? json(o.max_drift_h_m) : json(nullptr)}});
    if (o.points == 0) continue;
    drift2 += o.max_drift_h_m * o.max_drift_h_m;
    ++scored;
  }
  sj["outages"] = outs;
  sj["outage_max_drift_h_rms_m"] = scored ? json(std::sqrt(drift2 / static_cast<double>(scored))) : json(nullptr);
  json nis;
  for (std::size_t i = 0; i < est::kAidingSourceCount; ++i) {
    const ChiStats& s = metrics.nis[i];
    nis[est::kAidingSourceNames[i]] = {{"count", s.count}, {"mean", s.mean()}, {"inside_95", s.inside_fraction()}};
  }
  sj["nis"] = nis;
  sj["nees"] = {{"dof", metrics.nees_dof}, {"count", metrics.nees.count}, {"mean", metrics.nees.mean()},
                {"inside_95", metrics.nees.inside_fraction()},
                {"after_settling", {{"from_s", NavMetrics::kSettleS}, {"mean", metrics.nees_settled.mean()},
                                    {"inside_95", metrics.nees_settled.inside_fraction()}}}};
  json rejected = json::object(), accepted = json::object();
  for (std::size_t i = 0; i < est::kAidingSourceCount; ++i) {
    rejected[est::kAidingSourceNames[i]] = c.rejected[i];
    accepted[est::kAidingSourceNames[i]] = c.accepted[i];
  }
  sj["rejected"] = rejected;
  sj["accepted"] = accepted;
  sj["gnss"] = {{"epochs", epochs}, {"used", used}, {"dropped_outage", dropped_outage}, {"dropped_period", dropped_period},
                {"late", c.gnss_late}, {"overflow", c.gnss_overflow}};
  sj["corrupt_sentences"] = src.corrupt_sentences;
  sj["imu"] = {{"incomplete_rows", src.incomplete_rows}, {"time_anomalies", src.time_anomalies},
               {"non_finite_rows", src.non_finite_rows},
               {"first_anomaly", src.first_anomaly.empty() ? json(nullptr) : json(src.first_anomaly)}, {"non_increasing", c.imu_non_increasing}, {"gaps", c.imu_gaps},
               {"gap_total_s", c.imu_gap_total_s}, {"longest_gap_s", c.imu_longest_gap_s},
               {"invalid", c.imu_invalid}, {"clipped_samples", c.imu_clipped_samples}};
  // Health: whether this solution can be trusted, before any figure of merit.
  const bool lost_now = navigator->aligned() && (observer.last_flags() & est::nav_flag::kLost);
  const char* status = !navigator->aligned()  ? "not_aligned"
                       : lost_now             ? "lost"
                       : c.lost_total_s > 0.0 ? "lost_and_recovered"
                       : c.resets() > 0       ? "reset"
                                              : "ok";
  sj["health"] = {{"status", status},
                  {"lost_s", c.lost_total_s},
                  {"first_lost_t", c.lost_total_s > 0.0 ? json(c.first_lost_t_s) : json(nullptr)},
                  {"resets", {{"position", c.position_resets}, {"velocity", c.velocity_resets}, {"yaw", c.yaw_resets}}},
                  {"magnetometer_reanchors", c.mag_reanchors},
                  {"position_inflations", c.position_inflations},
                  {"first_reset_t", c.resets() ? json(c.first_reset_t_s) : json(nullptr)},
                  {"gnss_timeouts", c.gnss_timeouts},
                  {"gnss_timeout_s", c.gnss_timeout_total_s}};
  sj["noise"] = {{"gnss_velocity_sigma_m_s", navigator->gnss_velocity_sigma_m_s()},
                 {"gnss_velocity_learnt", opt.adapt_velocity_noise},
                 {"magnetometer_sigma_uT", navigator->mag_sigma_uT()},
                 {"magnetometer_learnt", opt.adapt_mag_noise}};
  sj["gnss_only_rmse"] = {{"pos_h_m", rms(metrics.gnss_sum_h2, metrics.gnss_compared)},
                          {"pos_v_m", rms(metrics.gnss_sum_v2, metrics.gnss_compared)},
                          {"fixes", metrics.gnss_compared}};
  json sens = json::object();
  static constexpr const char* kAxes[] = {"ax", "ay", "az", "gx", "gy", "gz"};
  for (Eigen::Index a = 0; a < est::kSensorAxes; ++a) {
    sens[kAxes[a]] = {{"estimate", flt.sensor_error(a)}, {"sigma", flt.sensor_error_sigma(a)}};
  }
  sj["sensor_errors_final"] = sens;

  if (!nav_out.close() || !innov_out.close()) {
    error = opt.out_dir + ": writing nav.csv / innovations.csv failed (disk full?)";
    return false;
  }
  std::ofstream so(out / "summary.json");
  so << sj.dump(2) << "\n";
  if (!so) {
    error = opt.out_dir + "/summary.json: write failed";
    return false;
  }
  totals.aligned = navigator->aligned();
  totals.rmse_pos_h_m = metrics.compared ? std::sqrt(metrics.sum_h2 / static_cast<double>(metrics.compared)) : NAN;
  return true;
}

}  // namespace sinu::replay
