#include "firmware/host/replay/replay_runner.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ekf/aiding/nonholonomic/nonholonomic.hpp"
#include "estimator/ins/rotation.hpp"
#include "firmware/board/nav_unit.hpp"
#include "firmware/host/dataset/truth_csv.hpp"
#include "firmware/host/replay/nav_metrics.hpp"
#include "firmware/host/replay/replay_source.hpp"

namespace sinu::replay {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

bool truth_point(const dataset::CsvRow& r, TruthPoint& p) {
  using namespace dataset::truth_col;
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

/// Compares each solution with truth.csv, counts, warns, and passes
/// everything on to the listeners.
class ReplayObserver final : public est::NavObserver {
 public:
  ReplayObserver(NavMetrics& metrics, std::span<ReplayListener* const> listeners, dataset::CsvReader* truth, bool warn)
      : metrics_(metrics), listeners_(listeners), truth_(truth), warn_(warn) {
    advance_truth();
  }

  void on_nav(const est::NavOutput& o) override {
    if (std::isnan(first_t_)) first_t_ = o.nav.t_s;
    compare_with_truth(o);
    prev_ = o;
    have_prev_ = true;
    if (warn_) warn(o);
    for (ReplayListener* l : listeners_) l->on_nav(o);
  }

  void on_innovation(const est::InnovationRecord& rec) override {
    metrics_.add_innovation(rec);
    for (ReplayListener* l : listeners_) l->on_innovation(rec);
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
      const bool p = resets & f::kPositionReset, v = resets & f::kVelocityReset, y = resets & f::kYawReset;
      std::fprintf(stderr, "sinu replay: warning: t=%.3f s: solution reset to GNSS (%s%s%s%s%s)\n", o.nav.t_s,
                   p ? "position" : "", p && (v || y) ? ", " : "", v ? "velocity" : "", v && y ? ", " : "",
                   y ? "yaw" : "");
    }
    if ((o.flags & f::kCourseTurned) && warnings_ < kMaxWarnings) {
      ++warnings_;
      std::fprintf(stderr, "sinu replay: warning: t=%.3f s: heading turned: the in-motion alignment contradicts the GNSS "
                   "course it was aligned on (%s)\n", o.nav.t_s, est::kCourseTurnedCause);
    }
    if (lost && !was_lost_ && warnings_ < kMaxWarnings) {
      ++warnings_;
      std::fprintf(stderr, "sinu replay: warning: t=%.3f s: solution LOST (GNSS fixes arriving, none fused)\n",
                   o.nav.t_s);
    }
    was_lost_ = lost;
  }
  static constexpr int kMaxWarnings = 5;

  void advance_truth() {
    have_truth_ = false;
    if (!truth_) return;
    while (truth_->next(row_) == dataset::ReadStatus::Row) {
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
        s.lon_rad = est::wgs84::lon_between_rad(prev_.nav.lon_rad, o.nav.lon_rad, a);
        s.h_m = prev_.nav.h_m + a * (o.nav.h_m - prev_.nav.h_m);
        s.v_n_m_s = prev_.nav.v_n_m_s + a * (o.nav.v_n_m_s - prev_.nav.v_n_m_s);
        s.q_nb = prev_.nav.q_nb.slerp(a, o.nav.q_nb);
        metrics_.add_truth(truth_pt_, s, o.P_nav);
      }
      advance_truth();
    }
  }

  NavMetrics& metrics_;
  std::span<ReplayListener* const> listeners_;
  dataset::CsvReader* truth_;
  bool warn_;
  dataset::CsvRow row_;
  TruthPoint truth_pt_;
  bool have_truth_ = false;
  est::NavOutput prev_;
  bool have_prev_ = false;
  double first_t_ = NAN;
  int warnings_ = 0;
  bool was_lost_ = false;
};

/// The one path from samples to the unit, whichever the source: GPS epochs
/// thinned by --gps-period and --outage, IMU samples as they come.
class UnitFeed final : public ReplayFeed {
 public:
  UnitFeed(board::NavUnit& unit, NavMetrics& metrics, const ReplayOptions& opt)
      : unit_(unit), metrics_(metrics), opt_(opt) {}

  void on_fix(const drivers::GpsFix& f) override {
    ++gnss.epochs;
    if (f.horizontal_only()) ++gnss.without_height;
    est::GnssObservation z;
    if (!unit_.observation(f, z)) return;
    const double t_valid = unit_.validity_time(z.arrival_s);
    if (gnss.observations == 0) gnss.first_t_s = t_valid;
    ++gnss.observations;
    gnss.last_t_s = t_valid;
    for (OutageDrift& o : metrics_.outages) {
      if (t_valid >= o.window.start_s && t_valid < o.window.start_s + o.window.duration_s) {
        ++o.fixes_withheld;
        ++gnss.dropped_outage;
        return;
      }
    }
    // Slower GPS: keep an epoch once at least a period (less 0.05 s of arrival jitter) has passed.
    if (opt_.gps_period_s > 0.0 && t_valid >= opt_.gps_period_from_s && t_valid - last_used_t_ < opt_.gps_period_s - 0.05) {
      ++gnss.dropped_period;
      return;
    }
    last_used_t_ = t_valid;
    ++gnss.used;
    unit_.push_fix(f, z);  // the fix's time too (the state file's age, the solution's UTC)
    if (z.has_height) metrics_.add_gnss({t_valid, z.lat_rad, z.lon_rad, z.h_m});  // "GNSS alone": the 3-D fixes
  }

  void on_imu(const est::ImuSample& s) override {
    unit_.push_imu(s);
    if (std::isnan(t_first)) t_first = s.t_s;
    t_last = s.t_s;
    ++imu_samples;
    excitation.add(s);
  }

  GnssFeedCounters gnss;
  std::uint64_t imu_samples = 0;
  Excitation excitation;
  double t_first = NAN, t_last = NAN;

 private:
  board::NavUnit& unit_;
  NavMetrics& metrics_;
  const ReplayOptions& opt_;
  double last_used_t_ = -1e300;
};

void collect(const board::NavUnit& unit, ReplayResult& r) {
  const est::Navigator& nav = unit.navigator();
  const est::ErrorStateFilter& f = nav.filter();
  r.states = static_cast<int>(f.layout().dim);
  const board::DenoiserSpec& d = unit.denoiser();
  r.denoiser = d.wavelet ? d.name + ":" + std::to_string(d.levels) : "none";
  if (d.wavelet && d.keep_above_sigma > 0.0) r.denoiser += fmt::format(", details beyond {:g} sigma kept", d.keep_above_sigma);
  if (nav.filter().noise().kind == est::NoiseModelKind::AutoRegressive)
    r.ar_rate_hz = 1.0 / nav.filter().noise().ar_sample_period_s;
  r.configured_gps_latency_s = unit.configured_gps_latency_s();
  r.gnss_latency_shift_s =
      f.layout().has(est::Effect::GpsLatency) && nav.aligned() ? f.gps_latency_s() - unit.configured_gps_latency_s() : 0.0;
  r.effects.clear();
  for (std::size_t e = 0; e < est::kEffectCount; ++e) {
    const auto ef = static_cast<est::Effect>(e);
    if (!f.layout().has(ef)) continue;
    EffectEstimate est{ef, {}, {}};
    for (Eigen::Index i = 0; i < est::kEffectDims[e]; ++i) {
      est.estimate.push_back(f.effect(ef, i));
      est.sigma.push_back(f.effect_sigma(ef, i));
    }
    r.effects.push_back(std::move(est));
  }
  for (Eigen::Index a = 0; a < est::kSensorAxes; ++a) {
    r.sensor_error[static_cast<std::size_t>(a)] = f.sensor_error(a);
    r.sensor_error_sigma[static_cast<std::size_t>(a)] = f.sensor_error_sigma(a);
  }
  r.aligned = nav.aligned();
  r.alignment = nav.alignment_result();
  r.scale = nav.scale_verdict();
  r.counters = nav.counters();
  const est::VehicleDetector& vd = nav.vehicle_detector();
  const Eigen::Vector3d mount_deg = est::vehicle_axes_in_use(f, vd.axes()).unit_euler_rad() * (180.0 / std::numbers::pi);
  r.vehicle = {nav.config().vehicle, nav.ground_vehicle(), vd.guess(), vd.decided_at_s(), vd.restored(), vd.lateral_rms_m_s(),
               vd.vertical_rms_m_s(), vd.moving_s(), vd.bank_per_g(), vd.on_bracket(), mount_deg.x(), mount_deg.y(), mount_deg.z()};
  r.gnss_velocity_sigma_m_s = nav.gnss_velocity_sigma_m_s();
  r.mag_sigma_uT = nav.mag_sigma_uT();
  r.gnss_position_scale = nav.gnss_position_scale();
  r.gnss_white_scale = nav.gnss_white_scale();
}

}  // namespace

bool run_replay(const ReplayOptions& opt, std::span<ReplayListener* const> listeners, ReplayResult& result,
                std::string& error, bool warn) {
  result = {};
  result.dataset = opt.in_dir;
  const std::unique_ptr<ReplaySource> source = open_replay_source(opt.in_dir, opt.imu, error);
  if (!source) return false;
  board::NavUnitConfig unit_cfg = opt.unit;
  source->full_scale(unit_cfg.accel_range_m_s2, unit_cfg.gyro_range_rad_s);  // a recording's driver settings

  const std::string truth_path = opt.truth_path.empty() ? source->default_truth() : opt.truth_path;
  dataset::CsvReader truth(dataset::kTruthSchema);
  result.has_truth = !truth_path.empty();
  if (result.has_truth && !truth.open(truth_path)) {
    error = truth.error().to_string();
    return false;
  }
  result.metrics.init(opt.outages, opt.unit.lever_arm_b_m);
  ReplayObserver observer(result.metrics, listeners, result.has_truth ? &truth : nullptr, warn);
  board::NavUnit unit;
  if (!unit.init(unit_cfg, &observer, error)) return false;
  for (ReplayListener* l : listeners) l->on_start(unit.navigator());

  UnitFeed feed(unit, result.metrics, opt);
  if (!source->run(feed, error)) return false;
  unit.flush();
  if (result.has_truth && truth.error().message.size()) {
    error = truth.error().to_string();
    return false;
  }
  result.note = source->note();
  if (!unit.state_note().empty()) result.note += (result.note.empty() ? "" : "; ") + unit.state_note();
  result.source = source->counters();
  if (!result.source.first_anomaly.empty()) {  // survived, but the user must know
    result.note += (result.note.empty() ? "" : "; ") + std::to_string(result.source.time_anomalies) +
                   " imu.csv row(s) with a time not increasing and " + std::to_string(result.source.non_finite_rows) +
                   " with a non-finite value were dropped; the first: " + result.source.first_anomaly;
  }
  result.imu_samples = feed.imu_samples;
  result.excitation = feed.excitation;
  result.duration_s = std::isnan(feed.t_first) ? 0.0 : feed.t_last - feed.t_first;
  result.gnss = feed.gnss;
  result.aligned_at_s = std::isnan(observer.first_t()) ? 0.0 : observer.first_t();
  result.last_flags = observer.last_flags();
  collect(unit, result);
  return true;
}

}  // namespace sinu::replay
