#pragma once
// SIGINT and SIGTERM (Ctrl-C, systemctl stop) ask the board's loops to stop:
// they end their turn, flush the recording and the logs, and exit 0.
#include <atomic>
#include <csignal>

namespace sinu::cli {

inline std::atomic<bool>& stop_requested() {
  static std::atomic<bool> stop{false};
  return stop;
}

extern "C" inline void sinu_on_stop_signal(int) { stop_requested() = true; }

inline void install_stop_signals() {
  stop_requested() = false;  // constructed here, before a handler can touch it
  struct sigaction sa {};
  sa.sa_handler = sinu_on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;  // no SA_RESTART: a blocking wait returns at once (EINTR) and the loop sees the flag
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

}  // namespace sinu::cli
