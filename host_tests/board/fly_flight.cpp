#include "host_tests/board/fly_flight.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "host_tests/support/run_process.hpp"

namespace sinu::test {

FlyFlight make_fly_flight(const TempDir& tmp, const std::string& name, int seconds, int seed) {
  FlyFlight f{tmp.file(name), tmp.file(name + "_q"), 0.0};
  const std::string raw = tmp.file(name + ".raw");
  EXPECT_EQ(run_sinu({"simulate", "flight", "--duration", std::to_string(seconds), "--seed", std::to_string(seed),
                      "--out", f.dir}).exit_code, 0);
  EXPECT_EQ(run_sinu({"convert", f.dir, raw}).exit_code, 0);
  EXPECT_EQ(run_sinu({"convert", raw, f.quantised}).exit_code, 0);
  std::ifstream in(f.quantised + "/imu.csv");
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  f.t0_s = std::stod(line.substr(0, line.find(',')));
  return f;
}

std::string write_fly_config(const TempDir& tmp, const std::string& name, const std::string& extra) {
  const std::string path = tmp.file(name + ".toml");
  std::ofstream out(path);
  out << "[navigation]\ncalibration = \"\"\nstate_file = \"" << tmp.file(name + "_state.json")
      << "\"\n\n[outputs.log]\nenabled = true\npath = \"" << tmp.file(name + "_nav.csv")
      << "\"\n\n" << extra;
  return path;
}

CsvNumbers read_csv_numbers(const std::string& path) {
  CsvNumbers out;
  std::ifstream in(path);
  std::getline(in, out.header);
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) row.push_back(c.empty() ? NAN : std::stod(c));
    if (!line.empty() && line.back() == ',') row.push_back(NAN);
    out.rows.push_back(std::move(row));
  }
  return out;
}

CsvDifference compare_rows(const CsvNumbers& a, const CsvNumbers& b, double t_max) {
  CsvDifference d;
  std::map<double, const std::vector<double>*> by_t;
  for (const auto& r : b.rows) by_t[r[0]] = &r;
  for (const auto& r : a.rows) {
    if (r[0] > t_max) continue;
    const auto it = by_t.find(r[0]);
    if (it == by_t.end()) continue;
    ++d.rows;
    const auto& o = *it->second;
    if (o.size() != r.size()) return {std::numeric_limits<double>::infinity(), d.rows};
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (std::isnan(r[i]) != std::isnan(o[i])) return {std::numeric_limits<double>::infinity(), d.rows};
      if (!std::isnan(r[i])) d.max_abs = std::max(d.max_abs, std::abs(r[i] - o[i]));
    }
  }
  return d;
}

}  // namespace sinu::test
