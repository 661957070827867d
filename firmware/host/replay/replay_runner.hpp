#pragma once
// `sinu replay`: a dataset folder or a raw HAL recording (replay_source.hpp)
// through the navigation unit (board/nav_unit.hpp), built the way `sinu fly`
// builds it. The result comes back as values (ReplayResult); each solution
// and each innovation goes to the listeners as it happens, and the files
// (nav.csv, innovations.csv, summary.json) are written by such listeners
// (replay_files.hpp).
#include <span>
#include <string>

#include "estimator/nav/navigator.hpp"
#include "firmware/host/replay/replay_options.hpp"
#include "firmware/host/replay/replay_result.hpp"

namespace sinu::replay {

class ReplayListener : public est::NavObserver {
 public:
  /// Once, before the first sample, with the navigator about to run.
  virtual void on_start(const est::Navigator&) {}
  void on_nav(const est::NavOutput&) override {}
  void on_innovation(const est::InnovationRecord&) override {}
};

/// Returns true on success; false with a one-line `error` (file:line:column
/// where a file is at fault). Allocates a bounded number of times, independent
/// of the input's length. `warn` prints a line on stderr when the solution is
/// reset or lost (the first few).
bool run_replay(const ReplayOptions& options, std::span<ReplayListener* const> listeners, ReplayResult& result,
                std::string& error, bool warn = true);

}  // namespace sinu::replay
