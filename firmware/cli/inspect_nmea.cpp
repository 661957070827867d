// sinu inspect nmea FILE [--json]: every fix of a raw NMEA capture (a gpsd
// log: '#' comment lines ignored) or of a dataset's gps.nmea, then counters.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <optional>
#include <string>

#include "drivers/gps/nmea_stream.hpp"
#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "firmware/host/dataset/nmea_log.hpp"

namespace sinu::cli {

namespace {

struct InspectNmeaOptions {
  std::string file;
  bool json = false;
};

/// A dataset gps.nmea starts (after any blank lines) with "<seconds>,$".
bool looks_like_gps_nmea(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line == "\r") continue;
    const auto comma = line.find(',');
    if (comma == std::string::npos || comma == 0 || comma + 1 >= line.size() || line[comma + 1] != '$') return false;
    return line.find_first_not_of("0123456789.+-eE") == comma;
  }
  return false;
}

std::string utc_text(const drivers::GpsFix& f) {
  const auto ms = f.utc_ms;
  char t[40];
  const int hh = static_cast<int>(ms / 3'600'000), mm = static_cast<int>(ms / 60'000 % 60);
  const int ss = static_cast<int>(ms / 1000 % 60), frac = static_cast<int>(ms % 1000);
  if (f.date)
    std::snprintf(t, sizeof t, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", f.date->year, f.date->month, f.date->day, hh, mm,
                  ss, frac);
  else
    std::snprintf(t, sizeof t, "%02d:%02d:%02d.%03d", hh, mm, ss, frac);
  return t;
}

template <class T>
nlohmann::json opt(const std::optional<T>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json fix_json(const drivers::GpsFix& f) {
  nlohmann::json j;
  j["utc"] = utc_text(f);
  j["lat"] = opt(f.lat_deg);
  j["lon"] = opt(f.lon_deg);
  j["alt_msl"] = opt(f.alt_msl_m);
  j["geoid_sep"] = opt(f.geoid_sep_m);
  j["quality"] = f.quality;
  j["sats"] = opt(f.sats);
  j["hdop"] = opt(f.hdop);
  j["speed_m_s"] = opt(f.speed_m_s);
  j["course_deg"] = opt(f.course_deg);
  j["has_position"] = f.has_position();
  if (f.has_gst) {
    j["sigma_lat_m"] = opt(f.sigma_lat_m);
    j["sigma_lon_m"] = opt(f.sigma_lon_m);
    j["sigma_alt_m"] = opt(f.sigma_alt_m);
  }
  return j;
}

void print_fix(const drivers::GpsFix& f, bool json) {
  if (json) {
    std::printf("%s\n", fix_json(f).dump().c_str());
    return;
  }
  std::printf("%s  %s", utc_text(f).c_str(), f.has_position() ? "fix   " : "no fix");
  if (f.lat_deg && f.lon_deg) std::printf("  %.8f %.8f", *f.lat_deg, *f.lon_deg);
  if (f.alt_msl_m) std::printf("  alt %.2f m", *f.alt_msl_m);
  if (f.sats) std::printf("  sats %d", *f.sats);
  if (f.speed_m_s) std::printf("  %.2f m/s", *f.speed_m_s);
  std::printf("\n");
}

nlohmann::json counters_json(const drivers::NmeaCounters& c, std::uint64_t fixes, std::uint64_t positions) {
  return {{"good", c.good},
          {"unknown_type", c.ignored},
          {"bad_checksum", c.bad_checksum},
          {"missing_checksum", c.missing_checksum},
          {"too_long", c.too_long},
          {"bad_framing", c.bad_framing},
          {"malformed_field", c.malformed_field},
          {"fixes", fixes},
          {"fixes_with_position", positions}};
}

int inspect_nmea(const InspectNmeaOptions& o) {
  std::uint64_t fixes = 0, positions = 0;
  drivers::GpsFix fix;
  auto emit = [&](const drivers::GpsFix& f) {
    ++fixes;
    positions += f.has_position() ? 1u : 0u;
    print_fix(f, o.json);
  };
  nlohmann::json counters;
  if (looks_like_gps_nmea(o.file)) {
    dataset::GpsLogReader reader;
    if (!reader.open(o.file)) {
      std::fprintf(stderr, "%s\n", reader.error().to_string().c_str());
      return kExitFailure;
    }
    dataset::ReadStatus s;
    while ((s = reader.next(fix)) == dataset::ReadStatus::Row) emit(fix);
    if (s == dataset::ReadStatus::Error) {
      std::fprintf(stderr, "%s\n", reader.error().to_string().c_str());
      return kExitFailure;
    }
    counters = counters_json(reader.counters(), fixes, positions);
    counters["skipped_lines"] = reader.log().skipped_lines();
    counters["late_sentences"] = reader.late_sentences();
    counters["format"] = "gps.nmea";
  } else {
    std::ifstream in(o.file, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "%s: cannot open\n", o.file.c_str());
      return kExitFailure;
    }
    drivers::NmeaStream stream(/*comments=*/true);
    char buffer[4096];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
      for (std::streamsize i = 0; i < in.gcount(); ++i)
        if (stream.push(buffer[i], 0.0, fix)) emit(fix);
    }
    while (stream.finish(0.0, fix)) emit(fix);
    const auto c = stream.counters();
    counters = counters_json(c.sentences, fixes, positions);
    counters["late_sentences"] = c.late_sentences;
    counters["interrupted"] = c.framing.interrupted;
    counters["resumed"] = c.framing.resumed;
    counters["noise_bytes"] = c.framing.noise_bytes;
    counters["comment_lines"] = c.framing.comment_lines;
    counters["format"] = "nmea capture";
  }
  if (o.json) std::printf("%s\n", nlohmann::json{{"counters", counters}}.dump().c_str());
  else std::printf("counters: %s\n", counters.dump().c_str());
  return kExitOk;
}

}  // namespace

void add_inspect_nmea_command(CLI::App& inspect, Action& action) {
  auto opts = std::make_shared<InspectNmeaOptions>();
  CLI::App* cmd = inspect.add_subcommand("nmea", "Decode an NMEA capture (gpsd log or gps.nmea): fixes and counters");
  cmd->add_option("FILE", opts->file, "A raw NMEA capture ('#' comments allowed) or a dataset's gps.nmea")->required();
  cmd->add_flag("--json", opts->json, "One JSON line per fix, then one JSON line of counters");
  cmd->callback([&action, opts] { action = [opts] { return inspect_nmea(*opts); }; });
}

}  // namespace sinu::cli
