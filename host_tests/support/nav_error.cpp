#include "host_tests/support/nav_error.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace sinu::test {

namespace {
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, ',');) out.push_back(c);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

}  // namespace

ErrorSeries error_series(const std::string& nav_csv, const std::string& truth_csv) {
  std::vector<double> tt, lat, lon;
  {
    std::ifstream in(truth_csv);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
      const auto c = cells(line);
      tt.push_back(std::stod(c[0]));
      lat.push_back(std::stod(c[1]));
      lon.push_back(std::stod(c[2]));
    }
  }
  ErrorSeries s;
  std::ifstream in(nav_csv);
  std::string line;
  std::getline(in, line);
  const auto header = cells(line);
  const auto flags_col = static_cast<std::size_t>(std::find(header.begin(), header.end(), "flags") - header.begin());
  std::size_t k = 0;
  while (std::getline(in, line)) {
    const auto c = cells(line);
    const double t = std::stod(c[0]);
    while (k + 1 < tt.size() && tt[k + 1] < t) ++k;
    if (k + 1 >= tt.size() || t < tt[k]) continue;
    const double a = (t - tt[k]) / (tt[k + 1] - tt[k]);
    const double la = lat[k] + a * (lat[k + 1] - lat[k]), lo = lon[k] + a * (lon[k + 1] - lon[k]);
    constexpr double kDeg = 3.14159265358979323846 / 180.0, kR = 6.371e6;
    const double dn = (std::stod(c[1]) - la) * kDeg * kR, de = (std::stod(c[2]) - lo) * kDeg * kR * std::cos(la * kDeg);
    s.t.push_back(t);
    s.err_h.push_back(std::hypot(dn, de));
    s.flags.push_back(static_cast<std::uint32_t>(std::stoul(c[flags_col])));
  }
  return s;
}

double rms_between(const ErrorSeries& s, double from, double to) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    if (s.t[i] < from || s.t[i] >= to) continue;
    sum += s.err_h[i] * s.err_h[i];
    ++n;
  }
  return n ? std::sqrt(sum / static_cast<double>(n)) : NAN;
}

double max_between(const ErrorSeries& s, double from, double to) {
  double m = 0.0;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (s.t[i] >= from && s.t[i] < to) m = std::max(m, s.err_h[i]);
  return m;
}

std::uint32_t flags_between(const ErrorSeries& s, double from, double to) {
  std::uint32_t m = 0;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (s.t[i] >= from && s.t[i] < to) m |= s.flags[i];
  return m;
}

}  // namespace sinu::test
