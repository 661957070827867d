#include "drivers/gps/nmea_parser.hpp"

#include <charconv>
#include <cmath>

namespace sinu::drivers {

namespace {

constexpr double kKnotToMps = 1852.0 / 3600.0;
constexpr double kKmhToMps = 1.0 / 3.6;

std::optional<int> parse_int(std::string_view f, bool& bad) {
  if (f.empty()) return std::nullopt;
  int v = 0;
  const auto [p, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc{} || p != f.data() + f.size()) {
    bad = true;
    return std::nullopt;
  }
  return v;
}

int digits2(std::string_view f, std::size_t at, bool& bad) {
  const char a = f[at], b = f[at + 1];
  if (a < '0' || a > '9' || b < '0' || b > '9') {
    bad = true;
    return 0;
  }
  return (a - '0') * 10 + (b - '0');
}

std::optional<double> parse_angle(std::string_view f, std::string_view hemi, std::size_t deg_digits, char pos,
                                  char neg, double max_deg, bool& bad) {
  if (f.empty() && hemi.empty()) return std::nullopt;
  const std::size_t dot = f.find('.');
  const std::size_t int_len = dot == std::string_view::npos ? f.size() : dot;
  if (int_len != deg_digits + 2 || hemi.size() != 1 || (hemi[0] != pos && hemi[0] != neg)) {
    bad = true;
    return std::nullopt;
  }
  bool b = false;
  const auto deg = parse_int(f.substr(0, deg_digits), b);
  const auto min = parse_number(f.substr(deg_digits), b);
  if (b || !deg || !min || *min < 0.0 || *min >= 60.0) {
    bad = true;
    return std::nullopt;
  }
  const double v = *deg + *min / 60.0;
  if (v > max_deg) {
    bad = true;
    return std::nullopt;
  }
  return hemi[0] == neg ? -v : v;
}

ParseResult decode_gga(const NmeaFields& f, GgaMessage& m, bool& bad) {
  if (f.count < 10) return (bad = true), ParseResult::Corrupt;
  m.utc_ms = parse_utc_time(f[1], bad);
  m.lat_deg = parse_latitude(f[2], f[3], bad);
  m.lon_deg = parse_longitude(f[4], f[5], bad);
  m.quality = parse_int(f[6], bad).value_or(0);
  m.sats = parse_int(f[7], bad);
  m.hdop = parse_number(f[8], bad);
  m.alt_msl_m = parse_number(f[9], bad);
  m.geoid_sep_m = parse_number(f[11], bad);
  return ParseResult::Message;
}

ParseResult decode_rmc(const NmeaFields& f, RmcMessage& m, bool& bad) {
  if (f.count < 10) return (bad = true), ParseResult::Corrupt;
  m.utc_ms = parse_utc_time(f[1], bad);
  m.valid = f[2] == "A";
  m.lat_deg = parse_latitude(f[3], f[4], bad);
  m.lon_deg = parse_longitude(f[5], f[6], bad);
  if (auto kn = parse_number(f[7], bad)) m.speed_m_s = *kn * kKnotToMps;
  m.course_deg = parse_number(f[8], bad);
  m.date = parse_ddmmyy(f[9], bad);
  if (f[12].size() == 1) m.mode = f[12][0];
  return ParseResult::Message;
}

ParseResult decode_vtg(const NmeaFields& f, VtgMessage& m, bool& bad) {
  if (f.count < 5) return (bad = true), ParseResult::Corrupt;
  if (f[2] == "T" || f.count >= 9) {  // NMEA 2.x: value,unit pairs
    m.course_deg = parse_number(f[1], bad);
    if (auto kmh = parse_number(f[7], bad)) m.speed_m_s = *kmh * kKmhToMps;
    else if (auto kn = parse_number(f[5], bad)) m.speed_m_s = *kn * kKnotToMps;
    if (f[9].size() == 1) m.mode = f[9][0];
  } else {  // old NMEA 1.5: course true, course magnetic, knots, km/h
    m.course_deg = parse_number(f[1], bad);
    if (auto kn = parse_number(f[3], bad)) m.speed_m_s = *kn * kKnotToMps;
  }
  return ParseResult::Message;
}

ParseResult decode_gsa(const NmeaFields& f, GsaMessage& m, bool& bad) {
  if (f.count < 18) return (bad = true), ParseResult::Corrupt;
  m.fix_type = parse_int(f[2], bad).value_or(0);
  for (std::size_t i = 3; i <= 14; ++i) m.used_sats += f[i].empty() ? 0 : 1;
  m.pdop = parse_number(f[15], bad);
  m.hdop = parse_number(f[16], bad);
  m.vdop = parse_number(f[17], bad);
  return ParseResult::Message;
}

ParseResult decode_gst(const NmeaFields& f, GstMessage& m, bool& bad) {
  if (f.count < 9) return (bad = true), ParseResult::Corrupt;
  m.utc_ms = parse_utc_time(f[1], bad);
  m.rms_m = parse_number(f[2], bad);
  m.sigma_lat_m = parse_number(f[6], bad);
  m.sigma_lon_m = parse_number(f[7], bad);
  m.sigma_alt_m = parse_number(f[8], bad);
  return ParseResult::Message;
}

ParseResult decode_zda(const NmeaFields& f, ZdaMessage& m, bool& bad) {
  if (f.count < 5) return (bad = true), ParseResult::Corrupt;
  m.utc_ms = parse_utc_time(f[1], bad);
  const auto day = parse_int(f[2], bad), month = parse_int(f[3], bad), year = parse_int(f[4], bad);
  if (day && month && year) {
    if (*day < 1 || *day > 31 || *month < 1 || *month > 12) bad = true;
    else m.date = UtcDate{*year, *month, *day};
  }
  return ParseResult::Message;
}

ParseResult decode_gll(const NmeaFields& f, GllMessage& m, bool& bad) {
  if (f.count < 7) return (bad = true), ParseResult::Corrupt;
  m.lat_deg = parse_latitude(f[1], f[2], bad);
  m.lon_deg = parse_longitude(f[3], f[4], bad);
  m.utc_ms = parse_utc_time(f[5], bad);
  m.valid = f[6] == "A" && f[7] != "N";  // NMEA 2.3 mode 'N': data not valid
  return ParseResult::Message;
}

template <class Msg, class Decoder>
ParseResult decode_into(const NmeaFields& f, NmeaMessage& out, Decoder decode, bool& bad) {
  Msg m;
  const ParseResult r = decode(f, m, bad);
  if (r == ParseResult::Message && !bad) out = m;
  return r;
}

}  // namespace

std::optional<double> parse_number(std::string_view f, bool& bad) {
  if (f.empty()) return std::nullopt;
  if (f.front() == '+') f.remove_prefix(1);
  double v = 0.0;
  const auto [p, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc{} || p != f.data() + f.size() || !std::isfinite(v)) {
    bad = true;
    return std::nullopt;
  }
  return v;
}

std::optional<UtcMs> parse_utc_time(std::string_view f, bool& bad) {
  if (f.empty()) return std::nullopt;
  if (f.size() < 6 || (f.size() > 6 && f[6] != '.')) {
    bad = true;
    return std::nullopt;
  }
  const int hh = digits2(f, 0, bad), mm = digits2(f, 2, bad), ss = digits2(f, 4, bad);
  double frac = 0.0;
  if (f.size() > 7) {
    const auto v = parse_number(f.substr(6), bad);  // ".40"
    frac = v.value_or(0.0);
  }
  if (bad || hh > 23 || mm > 59 || ss > 60) {
    bad = true;
    return std::nullopt;
  }
  return (static_cast<UtcMs>(hh) * 3600 + mm * 60 + ss) * 1000 + static_cast<UtcMs>(std::llround(frac * 1000.0));
}

std::optional<double> parse_latitude(std::string_view f, std::string_view hemi, bool& bad) {
  return parse_angle(f, hemi, 2, 'N', 'S', 90.0, bad);
}

std::optional<double> parse_longitude(std::string_view f, std::string_view hemi, bool& bad) {
  return parse_angle(f, hemi, 3, 'E', 'W', 180.0, bad);
}

std::optional<UtcDate> parse_ddmmyy(std::string_view f, bool& bad) {
  if (f.empty()) return std::nullopt;
  if (f.size() != 6) {
    bad = true;
    return std::nullopt;
  }
  const int dd = digits2(f, 0, bad), mo = digits2(f, 2, bad), yy = digits2(f, 4, bad);
  if (bad || dd < 1 || dd > 31 || mo < 1 || mo > 12) {
    bad = true;
    return std::nullopt;
  }
  // Two-digit year: NMEA's pivot, 80..99 -> 19xx (as gpsd does for old receivers).
  return UtcDate{yy >= 80 ? 1900 + yy : 2000 + yy, mo, dd};
}

ParseResult NmeaParser::parse(std::string_view sentence, NmeaMessage& out) {
  const SentenceCheck check = check_sentence(sentence);
  if (check != SentenceCheck::Ok) {
    last_error_ = to_string(check);
    switch (check) {
      case SentenceCheck::BadChecksum: ++counters_.bad_checksum; break;
      case SentenceCheck::MissingChecksum: ++counters_.missing_checksum; break;
      case SentenceCheck::TooLong: ++counters_.too_long; break;
      default: ++counters_.bad_framing; break;
    }
    return ParseResult::Corrupt;
  }
  const NmeaFields f = split_fields(sentence);
  const NmeaAddress addr = split_address(f[0]);
  bool bad = false;
  ParseResult r = ParseResult::Ignored;
  if (addr.talker != "P") {
    if (addr.type == "GGA") r = decode_into<GgaMessage>(f, out, decode_gga, bad);
    else if (addr.type == "RMC") r = decode_into<RmcMessage>(f, out, decode_rmc, bad);
    else if (addr.type == "VTG") r = decode_into<VtgMessage>(f, out, decode_vtg, bad);
    else if (addr.type == "GSA") r = decode_into<GsaMessage>(f, out, decode_gsa, bad);
    else if (addr.type == "GST") r = decode_into<GstMessage>(f, out, decode_gst, bad);
    else if (addr.type == "ZDA") r = decode_into<ZdaMessage>(f, out, decode_zda, bad);
    else if (addr.type == "GLL") r = decode_into<GllMessage>(f, out, decode_gll, bad);
  }
  if (bad) {
    last_error_ = "malformed field";
    ++counters_.malformed_field;
    return ParseResult::Corrupt;
  }
  if (r == ParseResult::Ignored) ++counters_.ignored;
  else ++counters_.good;
  return r;
}

}  // namespace sinu::drivers
