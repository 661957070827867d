#include "host_tests/support/nav_error.hpp"

#include <gtest/gtest.h>

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
  std::vector<double> tt, lat, lon, h, yaw, vd, roll, pitch;
  {
    std::ifstream in(truth_csv);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
      const auto c = cells(line);
      if (c.size() < 3 || c[1].empty() || c[2].empty()) continue;  // no position in this row
      tt.push_back(std::stod(c[0]));
      lat.push_back(std::stod(c[1]));
      lon.push_back(std::stod(c[2]));
      h.push_back(c.size() > 3 && !c[3].empty() ? std::stod(c[3]) : NAN);
      yaw.push_back(c.size() > 9 && !c[9].empty() ? std::stod(c[9]) : NAN);
      roll.push_back(c.size() > 7 && !c[7].empty() ? std::stod(c[7]) : NAN);
      pitch.push_back(c.size() > 8 && !c[8].empty() ? std::stod(c[8]) : NAN);
      vd.push_back(c.size() > 6 && !c[6].empty() ? std::stod(c[6]) : NAN);
    }
  }
  ErrorSeries s;
  std::ifstream in(nav_csv);
  std::string line;
  std::getline(in, line);
  const auto header = cells(line);
  const auto column = [&](const char* name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t flags_col = column("flags"), yaw_col = column("yaw"), vd_col = column("vd");
  const std::size_t roll_col = column("roll"), pitch_col = column("pitch");
  const std::size_t h_col = column("h"), sigma_pd_col = column("sigma_pd_m");
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
    // The nearer truth row's yaw (angles do not interpolate across +-180).
    const double yaw_true = a < 0.5 ? yaw[k] : yaw[k + 1];
    s.err_yaw_deg.push_back(std::remainder(std::stod(c[yaw_col]) - yaw_true, 360.0));
    s.err_vd_m_s.push_back(std::stod(c[vd_col]) - (vd[k] + a * (vd[k + 1] - vd[k])));
    s.err_tilt_deg.push_back(
        std::hypot(std::remainder(std::stod(c[roll_col]) - (roll[k] + a * (roll[k + 1] - roll[k])), 360.0),
                   std::stod(c[pitch_col]) - (pitch[k] + a * (pitch[k + 1] - pitch[k]))));
    s.err_height_m.push_back(std::stod(c[h_col]) - (h[k] + a * (h[k + 1] - h[k])));
    s.sigma_pd_m.push_back(sigma_pd_col < c.size() ? std::stod(c[sigma_pd_col]) : NAN);
  }
  return s;
}

double rms_of(const std::vector<double>& t, const std::vector<double>& x, double from, double to) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < from || t[i] >= to || std::isnan(x[i])) continue;
    sum += x[i] * x[i];
    ++n;
  }
  return n ? std::sqrt(sum / static_cast<double>(n)) : NAN;
}

double rms_between(const ErrorSeries& s, double from, double to) { return rms_of(s.t, s.err_h, from, to); }

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

namespace {
/// Column `name` of `line` under `header` (NaN and a test failure when it is missing).
double value_in(const std::string& header, const std::string& line, const std::string& name, const std::string& nav_csv) {
  const auto h = cells(header), v = cells(line);
  const auto at = static_cast<std::size_t>(std::find(h.begin(), h.end(), name) - h.begin());
  if (at < v.size()) return std::stod(v[at]);
  ADD_FAILURE() << name << " not in " << nav_csv;
  return NAN;
}
}  // namespace

double nav_value(const std::string& nav_csv, const std::string& name, NavRow row) {
  std::ifstream in(nav_csv);
  std::string header, line, chosen;
  std::getline(in, header);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    chosen = line;
    if (row == NavRow::First) break;
  }
  return value_in(header, chosen, name, nav_csv);
}

double nav_value_after(const std::string& nav_csv, const std::string& name, double after_first_s) {
  std::ifstream in(nav_csv);
  std::string header, line;
  std::getline(in, header);
  double t0 = NAN;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const double t = std::stod(line.substr(0, line.find(',')));
    if (std::isnan(t0)) t0 = t;
    if (t >= t0 + after_first_s) break;
  }
  return value_in(header, line, name, nav_csv);
}

}  // namespace sinu::test
