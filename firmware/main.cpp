// sinu: GPS-aided MEMS strapdown inertial navigation unit.
// One program for the companion computer (`sinu fly`) and its host modes.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"

int main(int argc, char** argv) {
  CLI::App app{"sinu: GPS-aided MEMS strapdown inertial navigation unit (wavelet-denoised IMU, "
               "GM/AR noise models, error-state EKF)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "sinu 0.1.0");
  sinu::cli::Action action;
  // On the board (SINU_BOARD_ONLY builds only these):
  sinu::cli::add_fly_command(app, action);
  sinu::cli::add_record_command(app, action);
  sinu::cli::add_bench_command(app, action);
  sinu::cli::add_calibrate_command(app, action);
#if SINU_HOST_MODES
  sinu::cli::add_inspect_command(app, action);
  sinu::cli::add_simulate_command(app, action);
  sinu::cli::add_denoise_command(app, action);
  sinu::cli::add_replay_command(app, action);
  sinu::cli::add_convert_command(app, action);
  sinu::cli::add_diagnose_command(app, action);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);  // prints help, 0
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the message and a hint to use --help
    return sinu::cli::kExitUsage;
  }
  if (!action) return sinu::cli::kExitUsage;
  try {
    return action();
  } catch (const std::exception& e) {  // last resort: never die without a word
    std::fprintf(stderr, "sinu: error: %s\n", e.what());
    return sinu::cli::kExitFailure;
  }
}
