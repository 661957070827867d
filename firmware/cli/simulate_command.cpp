// sinu simulate flight|static --out DIR --seed N [--duration S | --hours H]
//   [--imu-rate HZ] [--gps-rate HZ] [--effects FILE | --effects-random K]
//   [--unit-accel-errors] [--hidden-out FILE] [--corrupt-fraction F] [--site LAT,LON,H]
//   flight: [--airframe fixed-wing|multirotor]
//   static: [--positions N [--hold-s S] [--transition-s S]]
// Writes a dataset folder (dataset-format.md) and, optionally, the hidden
// truth (error-model parameters and effects) as JSON outside that folder.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "firmware/host/sim/effects/effect_list.hpp"
#include "firmware/host/sim/simulation.hpp"

namespace sinu::cli {

namespace {

struct SimulateCli {
  sim::SimOptions sim;
  std::string effects_file;
  int effects_random = -1;
  double hours = 0.0;
  std::string hidden_out;
  std::vector<double> site;
};

bool inside(const std::filesystem::path& file, const std::filesystem::path& dir) {
  std::error_code ec;
  const auto f = std::filesystem::weakly_canonical(std::filesystem::absolute(file, ec), ec);
  const auto d = std::filesystem::weakly_canonical(std::filesystem::absolute(dir, ec), ec);
  const auto rel = f.lexically_relative(d);
  return !rel.empty() && *rel.begin() != "..";
}

int simulate(SimulateCli c) {
  if (c.hours > 0.0) c.sim.duration_s = c.hours * 3600.0;
  if (c.site.size() == 3) c.sim.site_lat_lon_h = std::array<double, 3>{c.site[0], c.site[1], c.site[2]};
  // A multi-position session is for calibrating the unit's scale and misalignment: it has them.
  if (c.sim.positions > 1) c.sim.unit_accel_errors = true;
  if (!c.hidden_out.empty() && inside(c.hidden_out, c.sim.out_dir)) {
    std::fprintf(stderr, "sinu simulate: --hidden-out %s is inside the dataset folder %s; the truth must stay hidden\n",
                 c.hidden_out.c_str(), c.sim.out_dir.c_str());
    return kExitUsage;
  }
  std::string why;
  if (!sim::validate_options(c.sim, why)) {
    std::fprintf(stderr, "sinu simulate: %s\n", why.c_str());
    return kExitUsage;
  }
  dataset::Diagnostic err;
  if (!c.effects_file.empty()) {
    if (!std::filesystem::exists(c.effects_file)) {
      std::fprintf(stderr, "sinu simulate: %s: effects file does not exist\n", c.effects_file.c_str());
      return kExitUsage;
    }
    if (!sim::read_effects_file(c.effects_file, c.sim.effects, err)) {
      std::fprintf(stderr, "sinu simulate: %s\n", err.to_string().c_str());
      return kExitUsage;
    }
  } else if (c.effects_random >= 0) {
    sim::Rng rng(c.sim.seed, sim::RngStream::Effects);
    c.sim.effects = sim::draw_random_effects(static_cast<std::size_t>(c.effects_random), rng);
  }
  sim::SimResult result;
  if (!sim::run_simulation(c.sim, result, err)) {
    std::fprintf(stderr, "sinu simulate: %s\n", err.to_string().c_str());
    return kExitFailure;
  }
  if (!c.hidden_out.empty()) {
    std::ofstream out(c.hidden_out);
    out << result.hidden.dump(2) << '\n';
    if (!out) {
      std::fprintf(stderr, "sinu simulate: %s: cannot write the hidden truth\n", c.hidden_out.c_str());
      return kExitFailure;
    }
  }
  std::printf("%s: %llu IMU rows", c.sim.out_dir.c_str(), static_cast<unsigned long long>(result.imu_rows));
  if (c.sim.mode == sim::SimMode::Flight)
    std::printf(", %llu GPS sentences (%llu corrupted)", static_cast<unsigned long long>(result.gps_sentences),
                static_cast<unsigned long long>(result.corrupted_sentences));
  std::printf(", %zu effect(s)\n", result.hidden["effects"].size());  // with the unit's drawn ones
  return kExitOk;
}

void add_mode(CLI::App& parent, Action& action, sim::SimMode mode) {
  const bool flight = mode == sim::SimMode::Flight;
  auto c = std::make_shared<SimulateCli>();
  c->sim.mode = mode;
  c->sim.duration_s = flight ? 1800.0 : 8.0 * 3600.0;
  CLI::App* sub = parent.add_subcommand(
      flight ? "flight" : "static",
      flight ? "A UAV flight: imu.csv, gps.nmea, truth.csv, meta.json"
             : "A bench session for calibration (level and still, or held in --positions N attitudes): "
               "imu.csv, meta.json");
  sub->add_option("--out", c->sim.out_dir, "Dataset folder to write (created if needed)")->required();
  sub->add_option("--seed", c->sim.seed, "Random seed: the same seed gives the same dataset")->required();
  auto* duration = sub->add_option("--duration", c->sim.duration_s, "Length [s]")->capture_default_str();
  auto* hours = sub->add_option("--hours", c->hours, "Length [h] (instead of --duration)");
  duration->excludes(hours);
  sub->add_option("--imu-rate", c->sim.imu_rate_hz, "IMU sample rate [Hz]")->capture_default_str();
  if (flight) {
    sub->add_option("--gps-rate", c->sim.gps_rate_hz, "GPS fix rate [Hz]")->capture_default_str();
    sub->add_option("--corrupt-fraction", c->sim.gps.corrupt_fraction,
                    "Fraction of NMEA sentences deliberately corrupted")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    sub->add_option_function<std::string>(
           "--airframe", [c](const std::string& name) { sim::airframe_from_name(name, c->sim.airframe); },
           "What flies it: fixed-wing (the paper's UAV, 33-47 m/s) or multirotor (a survey at 3-8 m/s, vertical "
           "take-off and landing, hover stops)")
        ->default_str(sim::airframe_name(sim::Airframe::FixedWing))
        ->check(CLI::IsMember({sim::kAirframeNames[0], sim::kAirframeNames[1]}));
  }
  auto* fx = sub->add_option("--effects", c->effects_file, "Effects JSON file (docs/simulation.md)");
  const int n_effects = static_cast<int>(sim::kEffectNames.size());
  auto* fx_random = sub->add_option("--effects-random", c->effects_random,
                                    "Draw K random effects (0-" + std::to_string(n_effects) + ")")
                        ->check(CLI::Range(0, n_effects));
  fx->excludes(fx_random);
  sub->add_flag("--unit-accel-errors", c->sim.unit_accel_errors,
                "Give the unit its own accelerometer scale factors and misalignment, drawn from the seed where "
                "--effects sets none (a flight and a static session of one seed: the same values)");
  if (!flight) {
    sub->add_option("--positions", c->sim.positions,
                    "1: level (default); 6..26: held in N attitudes (the six faces, then tilted), turned between "
                    "them; implies --unit-accel-errors")
        ->capture_default_str();
    auto* hold = sub->add_option("--hold-s", c->sim.hold_s, "With --positions: each attitude held this long [s] "
                                                            "(default: the duration split evenly)");
    hold->excludes(duration)->excludes(hours);
    sub->add_option("--transition-s", c->sim.transition_s, "With --positions: time to turn between attitudes [s]")
        ->capture_default_str();
  }
  sub->add_option("--site", c->site, "LAT,LON,H: the site's latitude and longitude [deg] and ground height [m] "
                                     "instead of the seed's (high latitudes, the date line)")
      ->expected(3)
      ->delimiter(',');
  sub->add_option("--hidden-out", c->hidden_out, "Write the hidden truth (error model, effects) as JSON here; "
                                                 "never inside the dataset folder");
  sub->callback([&action, c] { action = [c] { return simulate(*c); }; });
}

}  // namespace

void add_simulate_command(CLI::App& app, Action& action) {
  CLI::App* simulate = app.add_subcommand("simulate", "Simulate a UAV flight or a static bench session as a dataset folder");
  simulate->require_subcommand(1);
  add_mode(*simulate, action, sim::SimMode::Flight);
  add_mode(*simulate, action, sim::SimMode::Static);
}

}  // namespace sinu::cli
