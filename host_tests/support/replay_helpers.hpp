#pragma once
// Helpers of the replay tests that run the sinu binary on edited copies of a
// dataset: copy a dataset with its gps.nmea filtered or edited line by line
// or with imu.csv columns rescaled (other units), replay and read
// summary.json, and the ten outages on the real drive.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "host_tests/support/read_json.hpp"
#include "host_tests/support/run_process.hpp"

namespace sinu::test {

/// `sinu simulate flight` into `out` with the effects JSON `effects_json`
/// (written next to it); the exit code.
inline int simulate_flight_with(const std::string& out, int seed, int seconds, const std::string& effects_json) {
  const std::string effects = out + "_effects.json";
  std::ofstream(effects) << effects_json;
  return run_sinu({"simulate", "flight", "--out", out, "--seed", std::to_string(seed), "--duration",
                   std::to_string(seconds), "--effects", effects})
      .exit_code;
}

/// Creates `dst` and copies every file of dataset `src` into it but `skip`,
/// which the caller writes edited.
inline void copy_dataset_except(const std::string& src, const std::string& dst, const std::string& skip) {
  std::filesystem::create_directories(dst);
  for (const auto& e : std::filesystem::directory_iterator(src)) {
    if (e.path().filename() != skip) std::filesystem::copy_file(e.path(), std::filesystem::path(dst) / e.path().filename());
  }
}

/// A copy of dataset `src` at `dst` whose gps.nmea keeps the lines for which
/// `keep(line)` is true (it may edit the line). Returns dst.
inline std::string copy_dataset_editing_gps(const std::string& src, const std::string& dst,
                                            const std::function<bool(std::string&)>& keep) {
  copy_dataset_except(src, dst, "gps.nmea");
  std::ifstream in(src + "/gps.nmea");
  std::ofstream out(dst + "/gps.nmea");
  for (std::string line; std::getline(in, line);) {
    if (keep(line)) out << line << '\n';
  }
  return dst;
}

/// A copy of dataset `src` at `dst` whose imu.csv rows (k from 0, after the
/// header) are given to `edit` as their fields to change. Returns dst.
inline std::string copy_dataset_editing_imu(const std::string& src, const std::string& dst,
                                            const std::function<void(std::size_t, std::vector<std::string>&)>& edit) {
  copy_dataset_except(src, dst, "imu.csv");
  std::ifstream in(src + "/imu.csv");
  std::ofstream out(dst + "/imu.csv");
  std::string line;
  std::getline(in, line);
  out << line << '\n';
  for (std::size_t k = 0; std::getline(in, line); ++k) {
    std::vector<std::string> fields;
    std::size_t start = 0;
    for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
      fields.push_back(line.substr(start, comma - start));
    fields.push_back(line.substr(start));
    edit(k, fields);
    for (std::size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << fields[i];
    out << '\n';
  }
  return dst;
}

/// A copy of dataset `src` at `dst` with imu.csv's named columns multiplied
/// by their factor (empty fields stay empty). Returns dst.
inline std::string with_scaled_columns(const std::string& src, const std::string& dst,
                                       const std::map<std::string, double>& factor) {
  std::ifstream in(src + "/imu.csv");
  std::string header;
  std::getline(in, header);
  std::vector<double> scale;
  std::stringstream names(header);
  for (std::string name; std::getline(names, name, ',');) scale.push_back(factor.count(name) ? factor.at(name) : 1.0);
  return copy_dataset_editing_imu(src, dst, [&](std::size_t, std::vector<std::string>& fields) {
    for (std::size_t i = 0; i < fields.size() && i < scale.size(); ++i) {
      if (fields[i].empty() || scale[i] == 1.0) continue;
      std::ostringstream v;
      v.precision(10);
      v << std::stod(fields[i]) * scale[i];
      fields[i] = v.str();
    }
  });
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
