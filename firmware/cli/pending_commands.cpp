// Subcommands that have not landed yet. Each has its --help; running one says
// so and exits 2. None prints made-up output.
#include <cstdio>

#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"

namespace sinu::app {

namespace {

struct Pending {
  const char* name;
  const char* description;
  const char* status;  // what it waits for
};

constexpr Pending kPending[] = {
    {"diagnose", "Compare the model with the measurements and name the missing effect",
     "planned; until then `sinu replay` writes innovations.csv and `sinu calibrate --report` the model-vs-data report"},
};

}  // namespace

void add_pending_commands(CLI::App& app, Action& action) {
  for (const Pending& p : kPending) {
    CLI::App* sub = app.add_subcommand(p.name, p.description);
    sub->allow_extras();  // its options are not defined yet; do not reject them
    sub->footer(std::string("Not available yet: ") + p.status + ".");
    sub->callback([&action, p] {
      action = [p] {
        std::fprintf(stderr, "sinu %s: not available yet (%s)\n", p.name, p.status);
        return kExitUsage;
      };
    });
  }
}

}  // namespace sinu::app
