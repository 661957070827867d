#pragma once
// Helpers of the replay tests that run the sinu binary on edited copies of a
// dataset: copy a dataset with its gps.nmea filtered or edited line by line,
// replay and read summary.json, and the ten outages on the real drive.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "host_tests/support/read_json.hpp"
#include "host_tests/support/run_process.hpp"

namespace sinu::test {

/// A copy of dataset `src` at `dst` whose gps.nmea keeps the lines for which
/// `keep(line)` is true (it may edit the line). Returns dst.
inline std::string copy_dataset_editing_gps(const std::string& src, const std::string& dst,
                                            const std::function<bool(std::string&)>& keep) {
  std::filesystem::create_directories(dst);
  for (const auto& e : std::filesystem::directory_iterator(src)) {
    if (e.path().filename() != "gps.nmea") std::filesystem::copy_file(e.path(), std::filesystem::path(dst) / e.path().filename());
  }
  std::ifstream in(src + "/gps.nmea");
  std::ofstream out(dst + "/gps.nmea");
  for (std::string line; std::getline(in, line);) {
    if (keep(line)) out << line << '\n';
  }
  return dst;
}

/// Runs `sinu` with `args` (which hold --out DIR) and returns DIR/summary.json.
inline nlohmann::json replay_summary(const std::vector<std::string>& args) {
  const auto r = run_sinu(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const auto out = std::find(args.begin(), args.end(), std::string("--out"));
  return read_json(*(out + 1) + "/summary.json");
}

/// The outage schedule as `--outage` takes it: ten 15-s outages, one
/// every 45 s from `first_start_s`.
inline std::string outage_schedule(double first_start_s) {
  std::string outages;
  for (int i = 0; i < 10; ++i) {
    if (i > 0) outages += ',';
    outages += std::to_string(first_start_s + 45.0 * i) + ":15";
  }
  return outages;
}

/// The schedule on drive_0708: from 60 s after the car first passes 3 m/s
/// (t = 243300.75 s, test_real_logs.cpp).
inline std::string drive_0708_outages() { return outage_schedule(243360.75); }

}  // namespace sinu::test
