#include "host_tests/support/run_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <thread>

#include "host_tests/support/temp_dir.hpp"

extern char** environ;

namespace sinu::test {

ProcessResult run_process(const std::vector<std::string>& argv, double signal_after_s, int signal) {
  TempDir tmp;
  const std::string out_path = tmp.file("stdout"), err_path = tmp.file("stderr");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  ProcessResult r;
  if (posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ) == 0) {
    if (signal_after_s > 0.0) {
      std::this_thread::sleep_for(std::chrono::duration<double>(signal_after_s));
      ::kill(pid, signal);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  }
  posix_spawn_file_actions_destroy(&actions);
  r.out = read_file(out_path);
  r.err = read_file(err_path);
  return r;
}

ProcessResult run_sinu(const std::vector<std::string>& args, double signal_after_s, int signal) {
  std::vector<std::string> argv{SINU_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_process(argv, signal_after_s, signal);
}

}  // namespace sinu::test
