#include "firmware/diagnose/innovation_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <vector>

namespace sinu::diag {

namespace {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(cell);
  return cells;
}

bool to_number(const std::string& s, double& v) {
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end != s.c_str() && *end == '\0' && std::isfinite(v);
}

struct NavPhases {
  std::vector<double> t;
  std::vector<Phase> phase;
  Phase at(double time) const {
    if (t.empty()) return Phase::Straight;
    const auto it = std::upper_bound(t.begin(), t.end(), time);
    const std::size_t k = it == t.begin() ? 0 : static_cast<std::size_t>(it - t.begin()) - 1;
    return phase[k];
  }
};

/// Opens a CSV file and reads its header line; false with `error` if it cannot.
bool open_csv(const std::string& path, std::ifstream& in, std::string& header, std::string& error) {
  in.open(path);
  if (!in || !std::getline(in, header)) {
    error = path + ": cannot open or empty";
    return false;
  }
  return true;
}

bool read_phases(const std::string& path, NavPhases& out, std::string& error) {
  std::ifstream in;
  std::string line;
  if (!open_csv(path, in, line, error)) return false;
  const auto header = split_csv(line);
  if (header.size() < 10 || header[0] != "t" || header[6] != "vd" || header[9] != "yaw") {
    error = path + ":1: header does not start with the truth.csv columns t,lat,lon,h,vn,ve,vd,roll,pitch,yaw";
    return false;
  }
  struct Row {
    double t, vn, ve, vd, yaw;
  };
  std::vector<Row> rows;
  std::size_t line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    const auto c = split_csv(line);
    Row r{};
    if (c.size() < 10 || !to_number(c[0], r.t) || !to_number(c[4], r.vn) || !to_number(c[5], r.ve) ||
        !to_number(c[6], r.vd) || !to_number(c[9], r.yaw)) {
      error = path + ":" + std::to_string(line_no) + ": expected numbers in t, vn, ve, vd, yaw";
      return false;
    }
    rows.push_back(r);
  }
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Row& a = rows[k == 0 ? 0 : k - 1];
    const Row& b = rows[k + 1 < rows.size() ? k + 1 : k];
    const double dt = b.t - a.t;
    double yaw_rate = 0.0, accel = 0.0;
    if (dt > 0.0) {
      yaw_rate = std::remainder(b.yaw - a.yaw, 360.0) / dt;
      accel = (std::hypot(b.vn, b.ve) - std::hypot(a.vn, a.ve)) / dt;
    }
    out.t.push_back(rows[k].t);
    out.phase.push_back(classify_phase(yaw_rate, rows[k].vd, accel, std::hypot(rows[k].vn, rows[k].ve)));
  }
  return true;
}

}  // namespace

void ComponentStats::add(double y, double s, bool accepted) {
  ++count;
  const double z = y / s;
  nll += 0.5 * z * z + std::log(s);
  z_sum += z;
  z2_sum += z * z;
  if (!accepted) ++rejected;
}

double InnovationStats::total_nll() const {
  double sum = 0.0;
  for (const ComponentStats& s : source) sum += s.nll;
  return sum;
}

bool read_innovation_stats(const std::string& dir, InnovationStats& out, std::string& error) {
  out = {};
  NavPhases phases;
  if (!read_phases(dir + "/nav.csv", phases, error)) return false;
  const std::string path = dir + "/innovations.csv";
  std::ifstream in;
  std::string line;
  if (!open_csv(path, in, line, error)) return false;
  if (line != "t,source,component,innovation,sigma,test_ratio,accepted") {
    error = path + ":1: unexpected header '" + line + "'";
    return false;
  }
  std::size_t line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    const auto c = split_csv(line);
    double t = 0.0, y = 0.0, s = 0.0;
    if (c.size() != 7 || !to_number(c[0], t) || !to_number(c[3], y) || !to_number(c[4], s)) {
      error = path + ":" + std::to_string(line_no) + ": expected t,source,component,innovation,sigma,test_ratio,accepted";
      return false;
    }
    const auto src = std::find(kSourceNames.begin(), kSourceNames.end(), c[1]);
    if (src == kSourceNames.end()) {
      error = path + ":" + std::to_string(line_no) + ": field 'source': unknown source '" + c[1] + "'";
      return false;
    }
    if (!(s > 0.0)) continue;  // no predicted sigma: nothing to score
    const auto k = static_cast<std::size_t>(src - kSourceNames.begin());
    const bool accepted = c[6] == "1";
    out.source[k].add(y, s, accepted);
    out.by_phase[k][static_cast<std::size_t>(phases.at(t))].add(y, s, accepted);
  }
  return true;
}

}  // namespace sinu::diag
