#pragma once
// Runs a program (by default the sinu binary under test) and captures its
// exit code, stdout and stderr.
#include <string>
#include <vector>

namespace sinu::test {

struct ProcessResult {
  int exit_code = -1;  // -1 if it did not exit normally (signal)
  std::string out, err;
};

/// `signal_after_s` > 0: sends `signal` to the process that long after its start.
ProcessResult run_process(const std::vector<std::string>& argv, double signal_after_s = 0.0, int signal = 15);
/// run_process({SINU_EXE, args...}, ...).
ProcessResult run_sinu(const std::vector<std::string>& args, double signal_after_s = 0.0, int signal = 15);

}  // namespace sinu::test
