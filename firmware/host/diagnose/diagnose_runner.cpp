#include "firmware/host/diagnose/diagnose_runner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>

#include "firmware/board/effect_selection.hpp"
#include "firmware/board/model_file.hpp"
#include "firmware/host/diagnose/configured_effects.hpp"
#include "firmware/host/diagnose/diagnosis_html.hpp"
#include "firmware/host/diagnose/diagnosis_report.hpp"
#include "firmware/host/replay/replay_files.hpp"

namespace sinu::diagnose {

namespace {

struct RunScore {
  InnovationStats stats;
  double rmse_pos_h_m = -1.0, rmse_att_deg = -1.0;
  double outage_drift_h_m = -1.0;  // RMS of the largest horizontal drift per outage (-1: none scored)
  InnovationSeries series;         // with keep_series only
  SolutionHealth health;
  double duration_s = 0.0;
  std::vector<replay::EffectEstimate> effects;
  replay::Excitation excitation;
};

constexpr const char* kAxis[] = {"x", "y", "z"};
constexpr double kG = 9.80665;

double or_minus_one(double v) { return std::isfinite(v) ? v : -1.0; }

/// One replay with `effects`, scored in memory; with `files_dir`, its nav.csv,
/// innovations.csv and summary.json are written there too; with `keep_series`,
/// its innovations over time are kept (the baseline's, for report.html).
bool replay_and_score(replay::ReplayOptions opt, est::EffectSet effects, const std::string& files_dir,
                      bool keep_series, RunScore& out, std::string& error) {
  opt.unit.effects = effects;
  InnovationStatsListener stats;
  InnovationSeriesListener series;
  replay::ReplayListener* const listeners[] = {&stats, &series};
  const std::span<replay::ReplayListener* const> used(listeners, keep_series ? 2 : 1);
  replay::ReplayResult result;
  const bool ok = files_dir.empty() ? replay::run_replay(opt, used, result, error, false)
                                    : replay::replay_to_folder(opt, files_dir, 10.0, result, error, used, false);
  if (!ok) return false;
  // No solution has no innovations: a report of "nothing missing" would look like a verdict.
  if (!result.aligned) {
    error = std::string("nothing to diagnose: the replay never aligned, no navigation solution (") +
            result.not_aligned_reason() + ")";
    return false;
  }
  out.stats = stats.stats();
  out.health = {result.health(), result.counters};
  out.duration_s = result.duration_s;
  out.series = series.take();
  out.rmse_pos_h_m = or_minus_one(result.rmse_pos_h_m());
  out.rmse_att_deg = or_minus_one(result.rmse_att_deg());
  out.outage_drift_h_m = or_minus_one(result.outage_drift_rms_m());
  out.effects = result.effects;
  out.excitation = result.excitation;
  return true;
}

// The baseline with each bias's random walk scaled up: a bias that shifted in
// flight shows as a likelihood gain no effect matches (a 0.5-deg/s gyro step
// +460 on a 20-min flight, a 0.3-m/s^2 accelerometer step +1000-2000). On the
// evaluation's 140 simulated flights the calibrated walk was right (clean
// flights: every scale loses) or the gain stayed below 222 where an effect
// was left half-explained: the threshold, 15 per minute of flight (300 for 20
// min), sits above that.
constexpr double kWalkScales[] = {3.0, 10.0, 30.0};
constexpr double kWalkGainPerMinute = 15.0, kMinWalkGain = 50.0;

double& bias_walk_scale(replay::ReplayOptions& opt, bool gyro) {
  return gyro ? opt.unit.gyro_bias_walk_scale : opt.unit.accel_bias_walk_scale;
}

bool test_bias_walks(const replay::ReplayOptions& opt, const est::EffectSet& model, const RunScore& baseline,
                     BiasWalkFinding& out, RunScore& best, std::string& error) {
  if (opt.unit.calib_path.empty()) return true;  // the built-in model's walks are guesses, not a claim
  out.tested = true;
  out.threshold = std::max(kMinWalkGain, kWalkGainPerMinute * baseline.duration_s / 60.0);
  out.nll_gain = -1e300;
  for (const bool gyro : {false, true}) {
    for (const double scale : kWalkScales) {
      replay::ReplayOptions trial = opt;
      bias_walk_scale(trial, gyro) = scale;
      RunScore score;
      if (!replay_and_score(trial, model, "", false, score, error)) return false;
      const double gain = baseline.stats.total_nll() - score.stats.total_nll();
      if (gain <= out.nll_gain) continue;
      out.nll_gain = gain;
      out.gyro = gyro;
      out.scale = scale;
      best = std::move(score);
    }
  }
  return true;
}

// Every flight phase with enough samples shows the source's misfit alike
// (within 0.6-1.6x its flight average): a noise level, not an effect.
bool alike_in_every_phase(const InnovationStats& st, std::size_t k) {
  const double overall = st.source[k].nis();
  for (const ComponentStats& p : st.by_phase[k]) {
    if (p.count < 50) continue;
    if (p.nis() < 0.6 * overall || p.nis() > 1.6 * overall) return false;
  }
  return true;
}

// The source's best-fitting flight phase (with enough samples): an effect
// shows where the vehicle excites it, a noise level set too small everywhere,
// so the best phase's NIS is the noise's share of the misfit.
double best_phase_nis(const InnovationStats& st, std::size_t k) {
  double best = st.source[k].nis();
  for (const ComponentStats& p : st.by_phase[k])
    if (p.count >= 50) best = std::min(best, p.nis());
  return best;
}

/// The baseline's and the final model's drift in the --outage windows (two more replays).
bool outage_drifts(replay::ReplayOptions opt, const std::vector<replay::Outage>& outages, Diagnosis& d,
                   std::string& error) {
  opt.outages = outages;
  for (Round* r : {&d.rounds.front(), &d.rounds.back()}) {
    RunScore s;
    opt.unit.relearn = r->relearnt;
    if (!replay_and_score(opt, r->model, "", false, s, error)) return false;
    r->outage_drift_h_m = s.outage_drift_h_m;
  }
  return true;
}

/// The input axis that drives component k (effects/*.hpp excited_by: a scale
/// its own axis, a misalignment or a g-sensitivity the column's), or -1.
Eigen::Index driving_axis(const est::EffectSpec& spec, Eigen::Index k) {
  if (spec.excited_by == est::Triad::None) return -1;
  Eigen::Index driver = k;
  if (spec.components == est::Components::OffDiagonal) driver = est::kOffDiagonal[static_cast<std::size_t>(k)][1];
  if (spec.components == est::Components::Matrix) driver = k % 3;
  return driver < 3 ? driver : -1;
}

// An accelerometer-driven component whose input axis spans less than this in
// the flight is not determined by it, whatever its sigma says: the filter's
// Jacobian takes the compensated specific force, and on an axis that stays
// near zero (y in coordinated flight) that is mostly the misalignment of
// gravity not yet learnt (a 25-mrad yz puts 0.25 m/s^2 on y): a regressor of
// estimate errors and noise, which the term fits to the coloured error left
// in the other axis (zy -44 +- 10 mrad against a true +18 on seed 4321, f_y
// within 0.1 m/s^2). 0.1 g is what a pull-up or a coordinated turn gives z.
constexpr double kMinDrivingSpan_m_s2 = 0.1 * 9.80665;

bool undriven(const est::EffectSpec& spec, Eigen::Index k, const replay::Excitation* x) {
  const Eigen::Index d = driving_axis(spec, k);
  if (x == nullptr || d < 0 || spec.excited_by != est::Triad::Accel) return false;
  return x->f_max_m_s2(d) - x->f_min_m_s2(d) < kMinDrivingSpan_m_s2;
}

}  // namespace

std::string untestable_reason(est::Effect effect, const replay::Excitation& x) {
  switch (est::spec(effect).needs) {
    case est::Needs::Temperature:
      if (x.temp_samples == 0) return "no temperature in imu.csv: a temperature coefficient cannot be told from the bias";
      if (x.temp_span_degC() < 2.0)
        return fmt::format("the temperature spans only {:.1f} degC (at least 2 degC separates a coefficient from the "
                           "bias; a warm-up on the bench does)", x.temp_span_degC());
      return "";
    case est::Needs::Magnetometer: return x.mag_samples == 0 ? "no magnetometer samples" : "";
    case est::Needs::Nothing: return "";
  }
  return "";
}

std::vector<CarriedFinding> carried_findings(const std::vector<replay::EffectEstimate>& effects,
                                             const est::EffectSet& skip, const DiagnoseOptions& o) {
  std::vector<CarriedFinding> out;
  for (const replay::EffectEstimate& e : effects) {
    const double resolution = est::spec(e.effect).report_resolution;
    if (!(resolution > 0.0) || skip.has(e.effect)) continue;
    CarriedFinding f;
    f.effect = e.effect;
    for (std::size_t k = 0; k < e.estimate.size(); ++k) {
      const double assumed = assumed_value(e.effect, static_cast<Eigen::Index>(k), o.replay.unit), d = std::abs(e.estimate[k] - assumed);
      f.assumed.push_back(assumed);
      f.estimate.push_back(e.estimate[k]);
      f.sigma.push_back(e.sigma[k]);
      // Judged on the components the flight determined (an unexcited axis keeps its prior sigma).
      if (e.sigma[k] > 0.0 && d >= o.min_significance * e.sigma[k]) {
        f.significance = std::max(f.significance, d / e.sigma[k]);
        f.deviation = std::max(f.deviation, d);
      }
    }
    if (f.deviation >= resolution) out.push_back(std::move(f));
  }
  return out;
}

void weigh_estimate(const replay::EffectEstimate& eff, const est::EffectPrior& file, const DiagnoseOptions& o,
                    CandidateResult& c, const replay::Excitation* x) {
  const est::Effect effect = c.effect;
  // Soft iron: a scale common to the three diagonal terms (xx yy zz) trades
  // against the Earth field's strength, itself a state, so it is no evidence
  // of soft iron; only the diagonal's differences and the cross terms are.
  auto common = [&](auto& v) { return effect == est::Effect::MagSoftIron ? (v[0] + v[1] + v[2]) / 3.0 : 0.0; };
  const double common_scale = common(eff.estimate), file_common = c.changed ? common(file.value) : 0.0;
  for (std::size_t k = 0; k < eff.estimate.size(); ++k) {
    const double v = eff.estimate[k];
    double sg = eff.sigma[k];
    c.estimate.push_back(v);
    c.sigma.push_back(sg);
    c.sigma_ratio.push_back(sg / est::spec(effect).initial_sigma);
    // Distance from what the model assumed without the states (the configured latency
    // and lever arm, zero otherwise), in sigmas; for a model-file effect
    // learnt again, from the file's value in both sigmas.
    double prior = assumed_value(effect, static_cast<Eigen::Index>(k), o.replay.unit);
    if (effect == est::Effect::MagSoftIron && k < 3) prior = common_scale;
    if (c.changed) {
      c.file_estimate.push_back(file.value[k]);
      c.file_sigma.push_back(file.sigma[k]);
      prior = file.value[k] + (k < 3 ? common_scale - file_common : 0.0);
      sg = std::hypot(sg, file.sigma[k]);
    }
    const double z = sg > 0.0 ? std::abs(v - prior) / sg : 0.0;
    c.held.push_back(undriven(est::spec(effect), static_cast<Eigen::Index>(k), x));
    if (c.held.back()) continue;
    c.significance = std::max(c.significance, z);
    // Only a component the flight determines can be implausible: one it left
    // near its prior (an unexcited axis) wanders at its prior sigma, which may
    // reach the plausible maximum without the data asking for it.
    if (z >= o.min_significance)
      c.plausibility = std::max(c.plausibility, std::abs(v - (k < 3 ? common_scale : 0.0)) /
                                                    est::spec(effect).plausible_max);
  }
}

void observability_notes(const CandidateResult& c, const replay::Excitation& x, std::vector<std::string>& out) {
  const est::EffectSpec& spec = est::spec(c.effect);
  for (std::size_t i = 0; i < c.sigma_ratio.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    const bool input_still = undriven(spec, k, &x);
    if (!(c.sigma_ratio[i] > 0.5) && !input_still) continue;
    const std::string what = std::string(spec.name) + (est::kEffectDims[static_cast<std::size_t>(c.effect)] > 1
                                                           ? std::string(" ") + est::effect_component_name(c.effect, k)
                                                           : "");
    std::string note =
        c.sigma_ratio[i] > 0.5
            ? fmt::format("{}: the flight left {:.0f} % of its prior sigma (weakly observable here)", what,
                          100.0 * c.sigma_ratio[i])
            : fmt::format("{}: its input never moved: not determined by this flight (held at its assumed value; "
                          "--apply leaves it at its prior)", what);
    // What the effect needs (effects/*.hpp excited_by): a scale the axis's own
    // range, a misalignment or a g-sensitivity the other axis's (the column).
    const Eigen::Index driver = driving_axis(spec, k);
    const bool accel_driven = spec.excited_by == est::Triad::Accel;
    const bool gyro_driven = spec.excited_by == est::Triad::Gyro;
    if (accel_driven && driver >= 0) {
      const double lo = x.f_min_m_s2(driver), hi = x.f_max_m_s2(driver);
      // What drives each body axis in flight (FRD): speed changes x, sideslip y, the load factor z.
      static constexpr const char* kManoeuvre[] = {"a speed change (a climb-out, a brake)",
                                                   "a sideslip or a knife-edge", "a pull-up, a push-over"};
      note += fmt::format("; specific force {} held within {:.1f}..{:.1f} m/s^2 for a second or more (a span of {:.2f} "
                          "g): {} or a bench tumble test (six positions) separates it from the bias",
                          kAxis[driver], lo, hi, (hi - lo) / kG, kManoeuvre[driver]);
    } else if (gyro_driven && driver >= 0) {
      const double span = std::max(std::abs(x.w_min_rad_s(driver)), std::abs(x.w_max_rad_s(driver))) * est::kRadToDeg;
      note += fmt::format("; rate {} never exceeded {:.0f} deg/s: faster turns or rolls about that axis reveal it",
                          kAxis[driver], span);
    } else if (spec.revealed_by != nullptr) {
      note += fmt::format("; revealed by {}", spec.revealed_by);
    }
    out.push_back(note);
  }
}

std::vector<std::string> noise_findings(const InnovationStats& st, bool effect_found) {
  // What sets each source's sigma in the model, for the advice.
  static constexpr const char* kSigmaFrom[kSources] = {"from the receiver's GST, or HDOP x UERE",
                                                        "--gps-vel-sigma, learnt", "--mag-sigma, learnt"};
  std::vector<std::string> out;
  for (std::size_t k = 0; k < kSources; ++k) {
    const ComponentStats& c = st.source[k];
    if (c.count < 100) continue;
    const double nis = c.nis(), factor = std::sqrt(nis);
    if (nis > 1.3) {
      out.push_back(fmt::format("{}: NIS {:.2f}: the innovations are {:.2f}x the sigma the filter claims: its noise ({}) "
                                "is {:.2f}x too small{}",
                                kSourceNames[k], nis, factor, kSigmaFrom[k], factor,
                                effect_found ? " even with the effects found"
                                             : " (no effect of the vocabulary explains the misfit)"));
    } else if (nis < 0.7 && nis > 0.0) {
      out.push_back(fmt::format("{}: NIS {:.2f}: its sigma ({}) is {:.2f}x too large (a generous sigma hides effects)",
                                kSourceNames[k], nis, kSigmaFrom[k], 1.0 / factor));
    }
  }
  return out;
}

bool run_diagnosis(const DiagnoseOptions& given, Diagnosis& out, std::string& error) {
  namespace fs = std::filesystem;
  // The candidates are judged on all the data (an outage's re-convergence
  // would be a misfit to explain); --outage windows are for the drift of the
  // model before and after (outage_drifts below).
  DiagnoseOptions o = given;
  o.replay.outages.clear();
  out = {};
  std::error_code ec;
  fs::create_directories(o.out_dir, ec);
  est::EffectSet model = o.replay.unit.effects;
  // Effects known from an earlier flight (--model-file) are part of the model:
  // not tried again as new effects, and written back by --apply with this
  // flight's estimates (the next flight starts from all of them). Each is a
  // candidate of another kind: learnt again from the vocabulary's prior, it
  // is named when this flight puts it elsewhere (an antenna moved, a
  // magnetometer remounted): "changed since the model file".
  std::array<est::EffectPrior, est::kEffectCount> known{};
  double file_imu_latency_s = 0.0;
  if (!o.replay.unit.model_path.empty() &&
      !board::read_model_file(o.replay.unit.model_path, model, known, file_imu_latency_s, error))
    return false;
  const double ran_imu_latency_s = board::imu_latency_in_use(o.replay.unit.imu_latency_s, file_imu_latency_s);
  RunScore current;
  const std::string baseline_dir = (fs::path(o.out_dir) / "baseline").string();
  DiagnoseOptions tuned = o;
  if (!replay_and_score(tuned.replay, model, baseline_dir, true, current, error)) return false;
  out.mag_sigma_given_uT = out.mag_sigma_uT = o.replay.unit.mag_sigma_uT;
  out.vel_sigma_given_m_s = out.vel_sigma_m_s = o.replay.unit.sigma.velocity_sigma_m_s;
  out.pos_sigma_scale_given = out.pos_sigma_scale = o.replay.unit.sigma.position_sigma_scale;
  // The magnetometer's and the GNSS velocity's sigmas are guesses (GST reports
  // only the position's), and a receiver's GST can be generous too (the real
  // quadcopter's u-blox: NIS 0.05, where a 0.5-m lever arm hid). A
  // too-generous sigma hides effects: when a source's NIS per component is
  // below 0.5, scale its sigma by sqrt(NIS) (the factor for white noise) so it is 1. Upwards only by what every flight phase shows
  // (a noise level set too small: a missing effect shows where the vehicle
  // excites it, in turns, climbs or speed changes, and inflating the sigma by
  // that would hide it): by the whole misfit when it is alike in every phase,
  // else by the best phase's when even that is well above 1 (an overconfident
  // sensor also drags the attitude, which misfits most in turns).
  auto sigma_factor = [&](std::size_t k) {
    const ComponentStats& c = current.stats.source[k];
    if (c.count <= 100) return 1.0;
    const double nis = c.nis(), floor = best_phase_nis(current.stats, k);
    if (nis < 0.5 || (nis > 1.5 && alike_in_every_phase(current.stats, k))) return std::sqrt(nis);
    if (floor > 1.5) return std::sqrt(floor);
    return 1.0;
  };
  const double mag_factor = sigma_factor(2), vel_factor = sigma_factor(1), pos_factor = sigma_factor(0);
  if (o.tune_noise_sigmas && (mag_factor != 1.0 || vel_factor != 1.0 || pos_factor != 1.0)) {
    tuned.replay.unit.sigma.position_sigma_scale = out.pos_sigma_scale =
        o.replay.unit.sigma.position_sigma_scale * pos_factor;
    tuned.replay.unit.mag_sigma_uT = out.mag_sigma_uT = std::max(0.05, o.replay.unit.mag_sigma_uT * mag_factor);
    tuned.replay.unit.sigma.velocity_sigma_m_s = out.vel_sigma_m_s =
        std::max(0.01, o.replay.unit.sigma.velocity_sigma_m_s * vel_factor);
    if (!replay_and_score(tuned.replay, model, baseline_dir, true, current, error)) return false;
  }
  // Without a calibration the built-in sensor model is a generic guess, usually
  // far too loose for a given unit: a loose model hides effects. Choose the
  // scale of its coloured-error variances by maximum likelihood of the
  // innovations (the same criterion that then judges the candidates).
  out.process_noise_scale = 1.0;
  out.calibrated = !o.replay.unit.calib_path.empty();
  if (o.tune_process_noise && o.replay.unit.calib_path.empty()) {
    for (const double scale : {0.3, 0.1, 0.03, 0.01}) {
      DiagnoseOptions trial = tuned;
      trial.replay.unit.process_noise_scale = scale;
      RunScore score;
      if (!replay_and_score(trial.replay, model, "", true, score, error)) return false;
      if (score.stats.total_nll() >= current.stats.total_nll()) break;  // the likelihood has peaked
      current = std::move(score);
      tuned = trial;
      out.process_noise_scale = scale;
    }
  }
  // What this flight cannot determine is held, not fitted: a term whose
  // input axis never moved stays at its assumed value in every candidate and
  // in the final model. (Free, the real drive's z scale, whose f_z never
  // leaves 1 g for a second, wandered to 9 % on vibration and road grade and
  // cost the scale candidate the x scale the drive does show.)
  bool baseline_holds = false;
  for (std::size_t e = 0; e < est::kEffectCount; ++e) {
    for (Eigen::Index k = 0; k < est::kEffectDims[e]; ++k)
      tuned.replay.unit.held[e][static_cast<std::size_t>(k)] =
          undriven(est::spec(static_cast<est::Effect>(e)), k, &current.excitation);
    baseline_holds |= model.has(static_cast<est::Effect>(e)) && !known[e].given && tuned.replay.unit.held[e].any();
  }
  // A baseline that carries such a term (--effects accel_scale) is scored
  // as the candidates will be, else they would gain or lose by the hold.
  if (baseline_holds && !replay_and_score(tuned.replay, model, baseline_dir, true, current, error)) return false;
  out.baseline_innovations = std::move(current.series);
  RunScore walk_score;
  if (!test_bias_walks(tuned.replay, model, current, out.bias_walk, walk_score, error)) return false;
  // A moved bias takes the first round; the effects then get their rounds from the widened walk.
  for (int r = 0; r < o.rounds + (out.bias_walk.named ? 1 : 0); ++r) {
    Round round;
    round.model = model;
    round.relearnt = tuned.replay.unit.relearn;
    round.stats = current.stats;
    round.health = current.health;
    round.rmse_pos_h_m = current.rmse_pos_h_m;
    round.rmse_att_deg = current.rmse_att_deg;
    round.outage_drift_h_m = current.outage_drift_h_m;
    // The candidates this round tries, then their replays in parallel (one per
    // core; each reads the data itself and shares nothing but `tuned`).
    struct Trial {
      est::Effect effect;
      bool relearn;  // a model-file effect from its prior, else a new one
    };
    std::vector<Trial> trials;
    for (std::size_t e = 0; e < est::kEffectCount; ++e) {
      const auto effect = static_cast<est::Effect>(e);
      // A model-file effect is in the model: tried re-learnt, until it has been.
      const bool relearn = known[e].given && !tuned.replay.unit.relearn.has(effect);
      if (!o.candidates.has(effect) || (model.has(effect) && !relearn)) continue;
      if (const std::string why = untestable_reason(effect, current.excitation); !why.empty()) {
        if (r == 0) out.skipped.push_back({effect, why});
        continue;
      }
      trials.push_back({effect, relearn});
    }
    std::vector<RunScore> scores(trials.size());
    std::vector<std::string> errors(trials.size());
    std::vector<char> ok(trials.size(), 0);
    std::atomic<std::size_t> next{0}, done{0};
    std::mutex progress;
    auto worker = [&] {
      for (std::size_t i = next++; i < trials.size(); i = next++) {
        est::EffectSet trial = model;
        replay::ReplayOptions opt = tuned.replay;
        if (trials[i].relearn) opt.unit.relearn.add(trials[i].effect);
        else trial.add(trials[i].effect);
        ok[i] = replay_and_score(opt, trial, "", false, scores[i], errors[i]) ? 1 : 0;
        const std::lock_guard<std::mutex> lock(progress);
        if (o.progress)
          std::fprintf(stderr, "diagnose: round %d: %zu/%zu candidates (%s%s)\n", r + 1, ++done, trials.size(),
                       est::spec(trials[i].effect).name, trials[i].relearn ? ", re-learnt" : "");
      }
    };
    const std::size_t threads =
        std::min<std::size_t>(trials.size(), std::max(1u, o.threads ? o.threads : std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    for (std::size_t i = 0; i < trials.size(); ++i) {
      if (!ok[i]) {
        error = errors[i];
        return false;
      }
    }
    for (std::size_t i = 0; i < trials.size(); ++i) {
      const est::Effect effect = trials[i].effect;
      const est::EffectPrior& file = known[static_cast<std::size_t>(effect)];
      const RunScore& score = scores[i];
      CandidateResult c;
      c.effect = effect;
      c.changed = trials[i].relearn;
      c.nll_gain = current.stats.total_nll() - score.stats.total_nll();
      // The replay's innovation likelihood is already marginal over the effect's
      // states (they start from their prior and every innovation carries their
      // uncertainty), so it pays for the extra parameters itself: the gain is
      // a log Bayes factor, and a BIC term on top would charge for them twice.
      c.evidence_threshold = o.min_log_evidence;
      for (const replay::EffectEstimate& eff : score.effects)
        if (eff.effect == effect) weigh_estimate(eff, file, o, c, &current.excitation);
      c.stats = score.stats;
      c.rmse_pos_h_m = score.rmse_pos_h_m;
      c.rmse_att_deg = score.rmse_att_deg;
      round.candidates.push_back(c);
    }
    // Best first: those that explain the data, by likelihood gain beyond the threshold.
    std::vector<std::size_t> order(round.candidates.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    auto rank = [&](std::size_t i) {
      const CandidateResult& c = round.candidates[i];
      return (c.explains(o.min_significance) ? 1e12 : 0.0) + c.nll_gain - c.evidence_threshold;
    };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank(a) > rank(b); });
    std::vector<CandidateResult> sorted;
    for (std::size_t i : order) sorted.push_back(round.candidates[i]);
    round.candidates = sorted;
    round.found = !round.candidates.empty() && round.candidates.front().explains(o.min_significance);
    // A bias that moved explains the baseline's misfit better than any effect:
    // name no effect for it (a step is no property of the unit), follow it with the wider walk.
    BiasWalkFinding& walk = out.bias_walk;
    if (r == 0 && walk.tested) {
      walk.best_effect_gain = round.candidates.empty() ? 0.0 : std::max(0.0, round.candidates.front().nll_gain);
      walk.named = walk.nll_gain > walk.threshold && walk.nll_gain > 2.0 * walk.best_effect_gain;
    }
    const bool walk_round = r == 0 && walk.named;
    if (walk_round) {
      round.found = false;
      bias_walk_scale(tuned.replay, walk.gyro) = walk.scale;
      current = std::move(walk_score);
    }
    if (round.found) {
      const CandidateResult& best = round.candidates.front();
      if (best.changed) {
        tuned.replay.unit.relearn.add(best.effect);
        out.changed.push_back(best.effect);
      } else {
        model.add(best.effect);
        out.missing.push_back(best.effect);
      }
      current = std::move(scores[order.front()]);
    }
    out.rounds.push_back(std::move(round));
    if (!out.rounds.back().found && !walk_round) break;
  }
  // The unit's properties the final model carried (latency, lever arm, hard
  // iron): its estimates against what was assumed. A model-file value is
  // judged by its re-learnt candidate instead ("changed since").
  est::EffectSet named_otherwise;
  for (est::Effect e : out.missing) named_otherwise.add(e);
  for (std::size_t e = 0; e < est::kEffectCount; ++e)
    if (known[e].given) named_otherwise.add(static_cast<est::Effect>(e));
  out.carried = carried_findings(current.effects, named_otherwise, o);
  // A latency below zero: the IMU's samples are late. The "after" is the
  // final model with them taken back, as --apply's model file will run it
  // (its outputs stamped at the instants they describe).
  bool retimed = false;
  for (const CarriedFinding& f : out.carried) {
    if (f.imu_latency_s() <= 0.0) continue;
    retimed = true;
    DiagnoseOptions later = tuned;
    later.replay.unit.imu_latency_s = ran_imu_latency_s + f.imu_latency_s();
    later.replay.unit.gps_latency_s = f.assumed[0];
    if (!replay_and_score(later.replay, model, "", true, current, error)) return false;
  }
  out.noise_findings = noise_findings(current.stats, out.model_changed());
  // Candidates the last round could not pin down: say so, and what would.
  if (!out.rounds.empty()) {
    for (const CandidateResult& c : out.rounds.back().candidates) observability_notes(c, current.excitation, out.observability);
  }
  // The final model's score, for the "after" column.
  Round last;
  last.model = model;
  last.relearnt = tuned.replay.unit.relearn;
  last.stats = current.stats;
  last.health = current.health;
  last.rmse_pos_h_m = current.rmse_pos_h_m;
  last.rmse_att_deg = current.rmse_att_deg;
  last.outage_drift_h_m = current.outage_drift_h_m;
  if (out.rounds.empty() || out.rounds.back().found || out.bias_walk.named || retimed) out.rounds.push_back(last);
  if (!given.replay.outages.empty() && !outage_drifts(tuned.replay, given.replay.outages, out, error)) return false;
  if (!o.apply_path.empty()) {
    // The final model's effects beyond the defaults (and the model file's, a
    // default's value among them), with the final run's estimates: the next
    // flight (replay, diagnose, fly) starts from them.
    std::vector<board::ModelEffect> found;
    const est::EffectSet defaults = board::default_effects();
    for (const replay::EffectEstimate& e : current.effects) {
      const bool from_file = known[static_cast<std::size_t>(e.effect)].given;
      if ((defaults.has(e.effect) && !from_file) || !model.has(e.effect)) continue;
      board::ModelEffect m{e.effect, e.estimate, e.sigma};
      // What this flight did not drive is not its finding: the next flight
      // starts that component from the prior (zy's -46 +- 12 mrad, fitted
      // through f_y's linearisation residue, would hold a sideslipping flight
      // 4 sigma off).
      for (std::size_t k = 0; k < m.estimate.size(); ++k) {
        if (from_file || !tuned.replay.unit.held[static_cast<std::size_t>(e.effect)][k]) continue;
        m.estimate[k] = 0.0;
        m.sigma[k] = est::spec(e.effect).initial_sigma;
      }
      found.push_back(m);
    }
    // A carried property goes in held to the resolution it is reported at, not
    // this flight's sigma: an airframe's hard iron changes with its battery and
    // payload, a receiver's latency with its settings, and the next flight's
    // states must still follow them.
    // The IMU's latency this flight ran with, and what a latency below zero adds to it.
    double imu_latency_s = ran_imu_latency_s;
    for (const CarriedFinding& f : out.carried) {
      if (model.has(f.effect) && !defaults.has(f.effect)) continue;  // written above (a model file's is never a finding)
      std::vector<double> sigma = f.sigma;
      for (double& s : sigma) s = std::max(s, est::spec(f.effect).report_resolution);
      std::vector<double> estimate = f.estimate;
      if (f.imu_latency_s() > 0.0) {  // the receiver as assumed, the rest the IMU's
        imu_latency_s += f.imu_latency_s();
        estimate = f.assumed;
      }
      found.push_back({f.effect, estimate, sigma});
    }
    if (!board::write_model_file(o.apply_path, found, imu_latency_s, "sinu diagnose " + o.replay.in_dir, error))
      return false;
    out.model_file = o.apply_path;
  }
  return write_diagnosis(tuned, out, error) && write_diagnosis_html(tuned, out, error);
}

}  // namespace sinu::diagnose
