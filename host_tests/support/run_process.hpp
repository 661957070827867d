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

ProcessResult run_process(const std::vector<std::string>& argv);
/// run_process({SINU_EXE, args...}).
ProcessResult run_sinu(const std::vector<std::string>& args);

}  // namespace sinu::test
