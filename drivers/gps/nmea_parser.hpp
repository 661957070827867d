#pragma once
// Sentence -> typed message, with the counters gpsd users expect. Any talker
// (GP, GN, GL, GA, GB, BD, ...). Sentences we do not decode (GSV, TXT,
// proprietary) are counted as "ignored"; they are not errors.
#include <cstdint>
#include <optional>
#include <string_view>

#include "drivers/gps/nmea_messages.hpp"
#include "drivers/gps/nmea_sentence.hpp"

namespace sinu::drivers {

struct NmeaCounters {
  std::uint64_t good = 0;              // decoded into a message
  std::uint64_t ignored = 0;           // valid but of a type we do not use
  std::uint64_t bad_checksum = 0;
  std::uint64_t missing_checksum = 0;  // usually a truncated sentence
  std::uint64_t too_long = 0;
  std::uint64_t bad_framing = 0;       // no '$', bad address, control bytes
  std::uint64_t malformed_field = 0;   // checksum fine, a field unreadable or too few fields
  std::uint64_t corrupt() const { return bad_checksum + missing_checksum + too_long + bad_framing + malformed_field; }
  std::uint64_t total() const { return good + ignored + corrupt(); }
};

enum class ParseResult { Message, Ignored, Corrupt };

class NmeaParser {
 public:
  /// Parses one sentence (no CR LF). On ParseResult::Message, `out` holds it.
  ParseResult parse(std::string_view sentence, NmeaMessage& out);
  const NmeaCounters& counters() const { return counters_; }
  /// Why the most recent Corrupt result happened, for diagnostics.
  const char* last_error() const { return last_error_; }

 private:
  NmeaCounters counters_;
  const char* last_error_ = "";
};

// Field decoders, exposed for tests. Each returns nullopt for an empty field
// and sets `bad` for a non-empty field it cannot read.
std::optional<double> parse_number(std::string_view f, bool& bad);
std::optional<UtcMs> parse_utc_time(std::string_view hhmmss, bool& bad);
std::optional<double> parse_latitude(std::string_view ddmm, std::string_view hemi, bool& bad);
std::optional<double> parse_longitude(std::string_view dddmm, std::string_view hemi, bool& bad);
std::optional<UtcDate> parse_ddmmyy(std::string_view ddmmyy, bool& bad);

}  // namespace sinu::drivers
