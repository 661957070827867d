// sinu diagnose --in DATASET|RAW [--truth truth.csv] [--calib calib.json] [--model gm|ar] [--effects BASELINE]
//   [--candidates NAME,...] [--rounds N] --out DIR
// Compares the model with the measurements (innovations against the filter's
// own sigmas, per source and flight phase), tries each effect the EKF can
// estimate, names the one(s) missing and shows the error before and after.
#include <cstdio>
#include <string>

#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "firmware/cli/navigation_options.hpp"
#include "firmware/host/diagnose/diagnose_runner.hpp"
#include "firmware/host/diagnose/diagnosis_report.hpp"
#include "firmware/host/replay/replay_options.hpp"

namespace sinu::cli {

namespace {

// The baseline is the default model (replay::default_effects: turn-on biases,
// the receiver's slowly varying error and its latency); --effects adds to it.
constexpr const char* kDefaultBaseline = "";
// Everything else the EKF can estimate (the vocabulary's diagnose candidates;
// the magnetometer's states come with it).
std::string default_candidates() {
  std::string out;
  for (const est::EffectSpec& e : est::kEffects)
    if (e.diagnose_candidate) out += (out.empty() ? "" : ",") + std::string(e.name);
  return out;
}

struct DiagnoseCliOptions {
  NavigationCliOptions nav{"gm", kDefaultBaseline};
  diagnose::DiagnoseOptions opt;
  bool quiet = false;
  bool apply = false;
  std::string candidates = default_candidates();
  std::string outages;
};

int run(DiagnoseCliOptions& c) {
  std::string error;
  if (!c.nav.resolve(error) || !board::parse_effects(c.candidates, c.opt.candidates, error) ||
      !replay::parse_outages(c.outages, c.nav.opt.outages, error)) {
    std::fprintf(stderr, "sinu diagnose: %s\n", error.c_str());
    return kExitUsage;
  }
  c.opt.replay = c.nav.opt;
  c.opt.progress = !c.quiet;
  if (c.apply) c.opt.apply_path = c.opt.out_dir + "/model.json";
  diagnose::Diagnosis d;
  if (!diagnose::run_diagnosis(c.opt, d, error)) {
    std::fprintf(stderr, "sinu diagnose: %s\n", error.c_str());
    return kExitFailure;
  }
  std::printf("%s  report: %s/report.md, %s/report.html\n", diagnose::diagnosis_summary(c.opt, d).c_str(),
              c.opt.out_dir.c_str(), c.opt.out_dir.c_str());
  return kExitOk;
}

}  // namespace

void add_diagnose_command(CLI::App& app, Action& action) {
  auto c = std::make_shared<DiagnoseCliOptions>();
  CLI::App* sub = app.add_subcommand("diagnose", "Compare the model with the measurements and name the missing effect");
  c->nav.add_to(*sub);
  sub->add_option("--candidates", c->candidates, "Effects to try, one at a time")->capture_default_str();
  sub->add_option("--rounds", c->opt.rounds, "How many effects to look for, one after the other")
      ->capture_default_str()
      ->check(CLI::Range(1, 5));
  sub->add_option("--min-evidence", c->opt.min_log_evidence,
                  "Name an effect only when it raises the innovations' log-likelihood by more than this, a log Bayes "
                  "factor (ln 100, 'decisive'; lower names weaker effects and more on clean flights: docs/diagnose.md)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e6));
  sub->add_option("--min-significance", c->opt.min_significance,
                  "Name an effect only when its estimate is at least this many sigma from the assumed value (in one "
                  "component)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 100.0));
  sub->add_option("--out", c->opt.out_dir,
                  "Output folder: report.md, report.html, diagnosis.json and the baseline replay (baseline/)")
      ->required();
  sub->add_option("--outage", c->outages,
                  "GPS outages START:DURATION[,...] in the dataset's t [s], as in replay: every run (baseline, "
                  "candidates, final) has them, and the drift in them is shown before and after (needs truth.csv)");
  sub->add_option("--threads", c->opt.threads, "Candidate replays at once (0: one per core)")->capture_default_str();
  sub->add_flag("--quiet", c->quiet, "No progress lines on stderr");
  sub->add_flag("--apply", c->apply,
                "Write what was found (effects, estimates, sigmas) to OUT/model.json, for --model-file of replay, "
                "diagnose and fly");
  sub->callback([&action, c] { action = [c] { return run(*c); }; });
}

}  // namespace sinu::cli
