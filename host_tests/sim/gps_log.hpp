#pragma once
// Reads a simulated gps.nmea back with the project's NMEA parser: every line
// with its arrival time, whether it passed the framing/checksum check, and
// the decoded message.
#include <optional>
#include <string>
#include <vector>

#include "drivers/gps/nmea_parser.hpp"
#include "firmware/host/dataset/nmea_log.hpp"

namespace sinu::test {

struct GpsLine {
  double arrival_s = 0.0;
  std::string sentence;
  bool checksum_ok = false;
  std::optional<drivers::NmeaMessage> message;
};

inline std::vector<GpsLine> read_gps_log(const std::string& path) {
  std::vector<GpsLine> out;
  dataset::NmeaLogReader log;
  EXPECT_TRUE(log.open(path)) << log.error().to_string();
  drivers::NmeaParser parser;
  dataset::NmeaLogLine line;
  while (log.next(line) == dataset::ReadStatus::Row) {
    GpsLine g;
    g.arrival_s = line.arrival_s;
    g.sentence = std::string(line.sentence);
    g.checksum_ok = drivers::check_sentence(line.sentence) == drivers::SentenceCheck::Ok;
    drivers::NmeaMessage msg;
    if (parser.parse(line.sentence, msg) == drivers::ParseResult::Message) g.message = msg;
    out.push_back(std::move(g));
  }
  EXPECT_EQ(log.skipped_lines(), 0u);
  return out;
}

/// Board time of a UTC time of day [ms], for the simulator's clock.
inline double board_time(drivers::UtcMs utc_ms, double utc_minus_board_s) {
  return static_cast<double>(utc_ms) * 1e-3 - utc_minus_board_s;
}

}  // namespace sinu::test
