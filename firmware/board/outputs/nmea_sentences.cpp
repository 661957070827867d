#include "firmware/board/outputs/nmea_sentences.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "estimator/nav/nav_health.hpp"
#include "firmware/board/outputs/error_ellipse.hpp"
#include "firmware/board/outputs/nmea_text.hpp"

namespace sinu::board {

namespace {

constexpr double kKnot_m_s = 1852.0 / 3600.0;
constexpr long long kMsPerDay = 86'400'000;
constexpr double kMaxMetres = 99999.999;  // any larger value is written as an empty field

/// The fields RMC, GGA and GST share, as text.
struct CommonFields {
  char time[16] = "";      // hhmmss.sss or empty
  char lat[24] = ",";      // ddmm.mmmmmm,N or two empty fields
  char lon[24] = ",";      // dddmm.mmmmmm,E or two empty fields
  bool fix = false;

  explicit CommonFields(const NavSolution& nav) {
    if (nav.has_utc) {
      const long long ms = ((nav.utc_ms % kMsPerDay) + kMsPerDay) % kMsPerDay;
      format_time_of_day(time, ms, 3);
    }
    const double lon_deg = std::remainder(nav.lon_deg, 360.0);
    fix = nmea_fix_valid(nav) && std::isfinite(nav.lat_deg) && std::isfinite(lon_deg) &&
          std::abs(nav.lat_deg) <= 90.0;
    if (fix) {
      format_angle(lat, nav.lat_deg, 2, 'N', 'S');
      format_angle(lon, lon_deg, 3, 'E', 'W');
    }
  }
};

/// "ddmmyy" of the UTC day, or empty.
void format_date(std::span<char> buf, const NavSolution& nav) {
  buf[0] = '\0';
  if (!nav.has_utc) return;
  const long long days = (nav.utc_ms >= 0 ? nav.utc_ms : nav.utc_ms - kMsPerDay + 1) / kMsPerDay;
  const std::chrono::year_month_day d{std::chrono::sys_days{std::chrono::days{days}}};
  std::snprintf(buf.data(), buf.size(), "%02u%02u%02d", static_cast<unsigned>(d.day()),
                static_cast<unsigned>(d.month()), static_cast<int>(d.year()) % 100);
}

/// Checksum and CR LF after the `n` characters snprintf reported; 0 if they
/// do not fit (cannot happen with the clamped fields: the longest is 88).
std::size_t finish(std::span<char> out, int n) {
  if (n < 0 || static_cast<std::size_t>(n) + 6 > out.size()) return 0;
  const std::size_t len = append_checksum(out, static_cast<std::size_t>(n));
  out[len] = '\r';
  out[len + 1] = '\n';
  out[len + 2] = '\0';
  return len + 2;
}

double sigma(const NavSolution& nav, Eigen::Index i) { return std::sqrt(std::max(nav.P_nav(i, i), 0.0)); }

}  // namespace

const char* to_string(NmeaTalker talker) { return talker == NmeaTalker::GN ? "GN" : "GP"; }

bool parse_talker(std::string_view text, NmeaTalker& out) {
  if (text == "GP") out = NmeaTalker::GP;
  else if (text == "GN") out = NmeaTalker::GN;
  else return false;
  return true;
}

bool nmea_fix_valid(const NavSolution& nav) { return nav.aligned && (nav.flags & est::nav_flag::kLost) == 0; }

std::size_t write_rmc(const NavSolution& nav, NmeaTalker talker, std::span<char> out) {
  if (out.size() < kNmeaSentenceMax) return 0;
  const CommonFields c(nav);
  char date[16], speed[24] = "", course[24] = "";
  format_date(date, nav);
  if (c.fix) {
    const double vn = nav.v_ned_m_s.x(), ve = nav.v_ned_m_s.y();
    format_fixed(speed, std::hypot(vn, ve) / kKnot_m_s, 3, 9999.999);
    double deg = std::atan2(ve, vn) * 180.0 / std::numbers::pi;
    if (deg < 0.0) deg += 360.0;
    if (deg >= 359.995) deg = 0.0;  // would print as 360.00
    format_fixed(course, deg, 2, 360.0);
  }
  const int n = std::snprintf(out.data(), out.size(), "$%sRMC,%s,%c,%s,%s,%s,%s,%s,,,%c", to_string(talker), c.time,
                              c.fix ? 'A' : 'V', c.lat, c.lon, speed, course, date, c.fix ? 'A' : 'N');
  return finish(out, n);
}

std::size_t write_gga(const NavSolution& nav, NmeaTalker talker, std::span<char> out) {
  if (out.size() < kNmeaSentenceMax) return 0;
  const CommonFields c(nav);
  char hdop[16], alt[24] = "", sep[24] = "";
  format_fixed(hdop, nav.hdop, 2, 99.99);
  if (c.fix) {
    format_fixed(alt, nav.h_ellipsoid_m - nav.geoid_sep_m, 3, kMaxMetres);
    format_fixed(sep, nav.geoid_sep_m, 3, 999.999);
  }
  const int sats = std::clamp(nav.satellites, 0, 99);
  const int n = std::snprintf(out.data(), out.size(), "$%sGGA,%s,%s,%s,%d,%02d,%s,%s,M,%s,M,,", to_string(talker),
                              c.time, c.lat, c.lon, c.fix ? 1 : 0, sats, hdop, alt, sep);
  return finish(out, n);
}

std::size_t write_gst(const NavSolution& nav, NmeaTalker talker, std::span<char> out) {
  if (out.size() < kNmeaSentenceMax) return 0;
  const CommonFields c(nav);
  char rms[24] = "", major[24] = "", minor[24] = "", orient[16] = "", s_lat[24] = "", s_lon[24] = "", s_alt[24] = "";
  if (c.fix) {
    const ErrorEllipse e = horizontal_error_ellipse(nav.P_nav(0, 0), nav.P_nav(0, 1), nav.P_nav(1, 1));
    // An INS has no pseudorange residuals: the RMS field carries the
    // position's 3-D RMS error, sqrt(trace P_pos), a quality figure that
    // grows and shrinks with the filter's.
    const double rms_m = std::sqrt(std::max(nav.P_nav(0, 0) + nav.P_nav(1, 1) + nav.P_nav(2, 2), 0.0));
    format_fixed(rms, rms_m, 3, kMaxMetres);
    format_fixed(major, e.semi_major_m, 3, kMaxMetres);
    format_fixed(minor, e.semi_minor_m, 3, kMaxMetres);
    format_fixed(orient, e.orientation_deg, 1, 180.0);
    format_fixed(s_lat, sigma(nav, 0), 3, kMaxMetres);
    format_fixed(s_lon, sigma(nav, 1), 3, kMaxMetres);
    format_fixed(s_alt, sigma(nav, 2), 3, kMaxMetres);
  }
  const int n = std::snprintf(out.data(), out.size(), "$%sGST,%s,%s,%s,%s,%s,%s,%s,%s", to_string(talker), c.time, rms,
                              major, minor, orient, s_lat, s_lon, s_alt);
  return finish(out, n);
}

std::size_t write_nmea_epoch(const NavSolution& nav, NmeaTalker talker, std::span<char> out) {
  if (out.size() < kNmeaEpochMax) return 0;
  std::size_t n = write_rmc(nav, talker, out);
  n += write_gga(nav, talker, out.subspan(n));
  n += write_gst(nav, talker, out.subspan(n));
  return n;
}

}  // namespace sinu::board
