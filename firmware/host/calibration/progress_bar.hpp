#pragma once
// A one-line progress bar with elapsed time and ETA on stderr, for long
// calibration sessions. Redrawn at most every 0.2 s; `finish` ends the line.
#include <chrono>
#include <cstdio>
#include <string>

namespace sinu::calibration {

class ProgressBar {
 public:
  ProgressBar(std::string label, double total, bool enabled);
  void update(double done);
  void finish();

 private:
  std::string label_;
  double total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace sinu::calibration
