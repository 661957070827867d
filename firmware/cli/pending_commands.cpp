// Subcommands whose issues have not landed yet. Each has its --help; running
// one says which issue brings it and exits 2. None prints made-up output.
#include <cstdio>

#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"

namespace sinu::app {

namespace {

struct Pending {
  const char* name;
  const char* description;
  int issue;
};

constexpr Pending kPending[] = {
    {"diagnose", "Compare the model with the measurements and name the missing effect", 6},
    {"record", "Record raw HAL traffic from the board's sensors", 7},
    {"convert", "Convert a raw HAL recording to a dataset folder and back", 7},
    {"fly", "Run the navigation unit on the companion computer", 7},
};

}  // namespace

void add_pending_commands(CLI::App& app, Action& action) {
  for (const Pending& p : kPending) {
    CLI::App* sub = app.add_subcommand(p.name, p.description);
    sub->allow_extras();  // its options are not defined yet; do not reject them
    sub->footer("Not available yet: this mode arrives with issue #" + std::to_string(p.issue) + ".");
    sub->callback([&action, p] {
      action = [p] {
        std::fprintf(stderr, "sinu %s: not available yet (issue #%d has not landed)\n", p.name, p.issue);
        return kExitUsage;
      };
    });
  }
}

}  // namespace sinu::app
