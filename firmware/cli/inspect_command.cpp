// sinu inspect dataset DIR [--json]: read every file of a dataset completely;
// print a summary, or the first error as file:line:column: message (exit 1).
#include <cstdio>
#include <string>

#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "firmware/host/dataset/dataset_summary.hpp"

namespace sinu::cli {

namespace {

struct InspectDatasetOptions {
  std::string dir;
  bool json = false;
};

int inspect_dataset(const InspectDatasetOptions& o) {
  dataset::DatasetSummary summary;
  dataset::Diagnostic err;
  if (!dataset::summarize_dataset(dataset::DatasetPaths{o.dir}, summary, err)) {
    std::fprintf(stderr, "%s\n", err.to_string().c_str());
    return kExitFailure;
  }
  const std::string text = o.json ? dataset::format_summary_json(summary) : dataset::format_summary(summary);
  std::fputs(text.c_str(), stdout);
  return kExitOk;
}

}  // namespace

void add_inspect_command(CLI::App& app, Action& action) {
  CLI::App* inspect = app.add_subcommand("inspect", "Validate and summarise a dataset, NMEA capture or recording");
  inspect->require_subcommand(1);

  auto opts = std::make_shared<InspectDatasetOptions>();
  CLI::App* ds = inspect->add_subcommand("dataset", "Validate a dataset folder completely and summarise it");
  ds->add_option("DIR", opts->dir, "Dataset folder (imu.csv, gps.nmea, truth.csv, meta.json)")->required();
  ds->add_flag("--json", opts->json, "Print the summary as JSON");
  ds->callback([&action, opts] { action = [opts] { return inspect_dataset(*opts); }; });
  add_inspect_nmea_command(*inspect, action);
  add_inspect_recording_command(*inspect, action);
}

}  // namespace sinu::cli
