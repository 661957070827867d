// sinu replay --in DATASET|RAW [--truth truth.csv] [--calib calib.json]
//   --model gm|ar [--effects ...] [--gps-period S] [--outage START:DURATION,...] --out DIR
// Runs a dataset folder, or a raw HAL recording through the drivers, through
// the INS/EKF; writes nav.csv, innovations.csv and summary.json; prints the
// navigation summary.
#include <cstdio>
#include <cmath>
#include <numbers>
#include <string>

#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "firmware/cli/navigation_options.hpp"
#include "firmware/host/replay/replay_files.hpp"

namespace sinu::cli {

namespace {

struct ReplayCliOptions {
  NavigationCliOptions nav{"ar", ""};
  std::string outages;
  std::string out_dir;
  double nav_rate_hz = 10.0;
  bool quiet = false;
};

std::string num(double v) {
  if (!std::isfinite(v)) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}
std::string num(std::uint64_t v) { return std::to_string(v); }

/// Why an --outage window withheld no fix (the summary line and the warning).
std::string nothing_withheld(const replay::ReplayResult& r) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "no GNSS epoch inside it (the GNSS runs t=%.1f..%.1f s, the dataset's own clock)",
                r.gnss.first_t_s, r.gnss.last_t_s);
  return buf;
}

void print_summary(const replay::ReplayOptions& opt, const replay::ReplayResult& r) {
  const est::NavCounters& c = r.counters;
  const replay::NavMetrics& m = r.metrics;
  std::printf("replay %s  model %s  states %d  aligned %s\n", r.dataset.c_str(),
              opt.unit.calib.kind == est::NoiseModelKind::GaussMarkov ? "gm" : "ar", r.states, r.aligned ? "yes" : "NO");
  // A solution that was lost or reset says so before any figure, and where to look for why.
  const auto why = [&] {
    std::printf("  why: sinu diagnose --in %s%s%s --out DIR, with the same options (a missing effect, a bias that "
                "moved, a noise level)\n",
                opt.in_dir.c_str(), opt.unit.calib_path.empty() ? "" : " --calib ", opt.unit.calib_path.c_str());
  };
  switch (r.health()) {
    case replay::HealthStatus::Lost:
      std::printf("  SOLUTION LOST at the end of the data (lost %s s from t=%s): the figures below are not a navigation "
                  "result\n", num(c.lost_total_s).c_str(), num(c.first_lost_t_s).c_str());
      why();
      break;
    case replay::HealthStatus::LostAndRecovered:
      std::printf("  SOLUTION WAS LOST for %s s (from t=%s) and recovered by %s reset(s)\n", num(c.lost_total_s).c_str(),
                  num(c.first_lost_t_s).c_str(), num(c.resets()).c_str());
      why();
      break;
    case replay::HealthStatus::Reset:
      std::printf("  solution RESET to GNSS %s time(s) (first at t=%s; position %s, velocity %s of which vertical %s, "
                  "yaw %s)\n",
                  num(c.resets()).c_str(), num(c.first_reset_t_s).c_str(), num(c.position_resets).c_str(),
                  num(c.velocity_resets).c_str(), num(c.vertical_resets).c_str(), num(c.yaw_resets).c_str());
      why();
      break;
    case replay::HealthStatus::NotAligned:
      std::printf("  NOT ALIGNED: no navigation solution (%s)\n", r.not_aligned_reason().c_str());
      if (r.gnss.without_height > 0 && r.gnss.used == 0)
        std::printf("  %s GNSS fixes without a height\n", num(r.gnss.without_height).c_str());
      break;
    case replay::HealthStatus::Ok: break;
  }
  const replay::VehicleOutcome& v = r.vehicle;
  if (v.configured == est::VehicleKind::Auto && v.guess != est::VehicleGuess::Undecided) {
    char mount[160] = "";
    if (v.on_bracket)
      std::snprintf(mount, sizeof mount, "; the unit sits turned %.1f deg, pitched %.1f deg, rolled %.1f deg on it",
                    v.unit_yaw_deg, v.unit_pitch_deg, v.unit_roll_deg);
    const char* constraint = v.guess == est::VehicleGuess::Ground ? "on (--vehicle air keeps it off)"
                                                                   : "on, then off again: the constraint did not hold";
    if (v.restored)
      std::printf("  vehicle: a ground vehicle, as the state file says (found before the restart%s): non-holonomic "
                  "constraint %s\n", mount, constraint);
    else
      std::printf("  vehicle: moves like a ground vehicle from t=%.1f s (velocity while moving, across the vehicle %.2f, "
                  "along its vertical %.2f m/s RMS%s): non-holonomic constraint %s\n",
                  v.detected_at_s, v.lateral_rms_m_s, v.vertical_rms_m_s, mount, constraint);
  }
  std::printf("  rmse: pos_h %s m  pos_v %s m  vel %s m/s  att %s deg  (%s truth points; GNSS alone: pos_h %s m  pos_v %s m)\n",
              num(r.rmse_pos_h_m()).c_str(), num(r.rmse_pos_v_m()).c_str(), num(r.rmse_vel_m_s()).c_str(),
              num(r.rmse_att_deg()).c_str(), num(m.compared).c_str(), num(r.gnss_rmse_pos_h_m()).c_str(),
              num(r.gnss_rmse_pos_v_m()).c_str());
  if (m.gnss_compared > 0 && std::abs(r.gnss_latency_shift_s) > 0.005 && !r.truth_is_gnss_input()) {
    std::printf("  GNSS alone: each fix at its time of validity as learnt (latency %.3f s); taken at the configured "
                "%.3f s, pos_h %s m\n", r.configured_gps_latency_s + r.gnss_latency_shift_s, r.configured_gps_latency_s,
                num(r.gnss_rmse_at_configured_pos_h_m()).c_str());
  }
  if (r.truth_is_gnss_input()) {
    std::printf("  note: truth.csv is the GNSS input itself (GNSS alone %s m from it): the rmse above is the solution's "
                "distance from its own fixes, not an accuracy; only GNSS outages (--outage) compare it with an "
                "independent reference\n", num(r.gnss_rmse_pos_h_m()).c_str());
  }
  for (const replay::OutageDrift& o : m.outages) {
    if (o.fixes_withheld == 0) {
      std::printf("  outage %.1f s +%.0f s: NOTHING WITHHELD: %s\n", o.window.start_s, o.window.duration_s,
                  nothing_withheld(r).c_str());
      continue;
    }
    std::printf("  outage %.1f s +%.0f s: max horizontal drift %s m\n", o.window.start_s, o.window.duration_s,
                o.points ? num(o.max_drift_h_m).c_str() : "n/a (no truth point inside it)");
  }
  if (!m.outages.empty()) std::printf("  outage drift RMS %s m\n", num(r.outage_drift_rms_m()).c_str());
  const auto pos = static_cast<std::size_t>(est::AidingSource::GnssPosition);
  std::printf("  NIS gnss_position mean %s (inside 95%%: %s), NEES mean %s (%d dof, inside 95%%: %s)\n",
              num(m.nis[pos].mean()).c_str(), num(m.nis[pos].inside_fraction()).c_str(), num(m.nees.mean()).c_str(),
              m.nees_dof, num(m.nees.inside_fraction()).c_str());
  std::printf("  rejected: position %s velocity %s magnetometer %s; corrupt sentences %s\n",
              num(c.rejected[pos]).c_str(), num(c.rejected[static_cast<std::size_t>(est::AidingSource::GnssVelocity)]).c_str(),
              num(c.rejected[static_cast<std::size_t>(est::AidingSource::Magnetometer)]).c_str(),
              num(r.source.corrupt_sentences).c_str());
  if (r.aligned && std::isfinite(r.alignment.course_turn_rad))
    std::printf("  heading: aligned on the GNSS course, turned %s deg at t=%.1f s where the in-motion alignment contradicted "
                "it (%s)\n",
                num(r.alignment.course_turn_rad * 180.0 / std::numbers::pi).c_str(), r.alignment.course_turn_t_s,
                est::kCourseTurnedCause);
  if (r.aligned && r.alignment.field_corrected_by_saved_iron)
    std::printf("  heading: from the field as the state file's iron corrects it (the iron has not moved since the "
                "save: the corrected field is the Earth's)\n");
  if (r.aligned && r.alignment.saved_iron_refused)
    std::printf("  heading: from the field as read: the state file's iron does not make it the Earth's (the iron has "
                "moved since it was saved, a battery or payload swapped), and the iron is learnt again\n");
  if (r.aligned && r.alignment.saved_biases == est::SavedBiases::Kept)
    std::printf("  turn-on biases: the state file's, kept: the rest measured the same gyro bias and accelerometer bias "
                "along gravity (no power cycle), so the saved accelerometer bias across gravity levels the unit\n");
  if (r.aligned && r.alignment.saved_biases == est::SavedBiases::Moved)
    std::printf("  turn-on biases: the rest measured other ones than the state file's (a power cycle): learnt "
                "again\n");
  if (const std::string why_no_mag = r.mag_refused_reason(); !why_no_mag.empty())
    std::printf("  magnetometer NOT USED: %s\n", why_no_mag.c_str());
  if (r.gnss.without_height > 0 && r.gnss.used > 0)
    std::printf("  GNSS: %s epoch(s) with a position but no height (their GGA missing or corrupt): %s fused north and "
                "east only\n",
                num(r.gnss.without_height).c_str(), num(c.horizontal_fixes).c_str());
  if (c.course_held > 0)
    std::printf("  GNSS: %s velocity epoch(s) with the course held by the receiver at low speed (the same course to the "
                "digit while the speed changes): fused as zero within their speed, not as a velocity\n",
                num(c.course_held).c_str());
  if (c.imu_clipped_samples > 0 || c.imu_gaps > 0 || c.imu_invalid > 0 || c.imu_non_increasing > 0 || c.gnss_timeouts > 0) {
    std::printf("  faults: IMU clipped %s samples, %s gaps (longest %s s), %s dropped (NaN %s, time %s); GNSS timeouts %s "
                "(%s s dead reckoning)\n",
                num(c.imu_clipped_samples).c_str(), num(c.imu_gaps).c_str(), num(c.imu_longest_gap_s).c_str(),
                num(c.imu_invalid + c.imu_non_increasing).c_str(), num(c.imu_invalid).c_str(),
                num(c.imu_non_increasing).c_str(), num(c.gnss_timeouts).c_str(), num(c.gnss_timeout_total_s).c_str());
  }
  if (c.gyro_bias_releases > 0 || c.mag_reanchors > 0) {
    std::printf("  heading misfit: gyro bias about the vertical released %s time(s) (the magnetometer's heading check "
                "or a yaw reset), hard iron re-anchored %s time(s)\n",
                num(c.gyro_bias_releases).c_str(), num(c.mag_reanchors).c_str());
  }
}

int run(ReplayCliOptions& c) {
  std::string error;
  replay::ReplayOptions& opt = c.nav.opt;
  if (!c.nav.resolve(error) || !replay::parse_outages(c.outages, opt.outages, error)) {
    std::fprintf(stderr, "sinu replay: %s\n", error.c_str());
    return kExitUsage;
  }
  replay::ReplayResult result;
  if (!replay::replay_to_folder(opt, c.out_dir, c.nav_rate_hz, result, error)) {
    std::fprintf(stderr, "sinu replay: %s\n", error.c_str());
    return kExitFailure;
  }
  if (!result.note.empty()) std::fprintf(stderr, "sinu replay: note: %s\n", result.note.c_str());
  // Lost and reset have their warning as they happen; never aligning has none until now.
  if (result.health() == replay::HealthStatus::NotAligned) {
    std::fprintf(stderr, "sinu replay: warning: never aligned: no navigation solution (%s)\n",
                 result.not_aligned_reason().c_str());
  }
  if (const std::string why_no_mag = result.mag_refused_reason(); !why_no_mag.empty())
    std::fprintf(stderr, "sinu replay: warning: magnetometer not used: %s\n", why_no_mag.c_str());
  for (const replay::OutageDrift& o : result.metrics.outages) {
    if (o.fixes_withheld > 0) continue;
    std::fprintf(stderr, "sinu replay: warning: --outage %g:%g withholds nothing: %s\n", o.window.start_s,
                 o.window.duration_s, nothing_withheld(result).c_str());
  }
  if (!c.quiet) print_summary(opt, result);
  return kExitOk;
}

}  // namespace

void add_replay_command(CLI::App& app, Action& action) {
  auto c = std::make_shared<ReplayCliOptions>();
  replay::ReplayOptions& opt = c->nav.opt;
  CLI::App* sub = app.add_subcommand(
      "replay", "Replay a dataset or a raw recording through the INS/EKF and write the navigation solution");
  c->nav.add_to(*sub);
  sub->add_option("--gps-period", opt.gps_period_s, "Use one GPS epoch every S seconds (0: all)");
  sub->add_option("--gps-period-from", opt.gps_period_from_s,
                  "Start the slower GPS of --gps-period at this dataset time [s] (every epoch before: the paper's "
                  "Table 5 slows the updates of an aligned, converged filter)");
  sub->add_option("--outage", c->outages, "GPS outages START:DURATION[,...] in the dataset's t [s]");
  sub->add_option("--state-file", opt.unit.state_path,
                  "The unit's state file, as `sinu fly` keeps it: read at the start (a restart: used when saved at "
                  "most --state-max-age s before the first fix), written every few seconds once aligned");
  sub->add_option("--state-max-age", opt.unit.state_max_age_s, "Oldest state file a restart uses [s]")
      ->capture_default_str();
  sub->add_option("--nav-rate", c->nav_rate_hz, "nav.csv rows per second (0: every IMU sample)")->capture_default_str();
  sub->add_option("--out", c->out_dir, "Output folder")->required();
  sub->add_flag("--quiet", c->quiet, "Do not print the summary");
  sub->callback([&action, c] { action = [c] { return run(*c); }; });
}

}  // namespace sinu::cli
