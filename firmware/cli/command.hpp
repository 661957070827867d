#pragma once
// Each mode adds its subcommand to the CLI and, when chosen, sets the action
// main() runs after parsing. Actions return an exit code (cli/exit_codes.hpp).
#include <CLI/CLI.hpp>
#include <functional>

namespace sinu::cli {

using Action = std::function<int()>;

void add_inspect_command(CLI::App& app, Action& action);
void add_inspect_nmea_command(CLI::App& inspect, Action& action);
void add_inspect_recording_command(CLI::App& inspect, Action& action);
void add_simulate_command(CLI::App& app, Action& action);
void add_denoise_command(CLI::App& app, Action& action);
void add_calibrate_command(CLI::App& app, Action& action);
void add_replay_command(CLI::App& app, Action& action);
void add_record_command(CLI::App& app, Action& action);
void add_convert_command(CLI::App& app, Action& action);
void add_fly_command(CLI::App& app, Action& action);
void add_bench_command(CLI::App& app, Action& action);
void add_diagnose_command(CLI::App& app, Action& action);

}  // namespace sinu::cli
