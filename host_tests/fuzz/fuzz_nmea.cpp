// libFuzzer: arbitrary bytes through the NMEA lexer, parser and fix
// assembler (as from a serial line), and each line straight into the parser
// (as from gps.nmea). Checks the invariants a user relies on.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "drivers/gps/nmea_parser.hpp"
#include "drivers/gps/nmea_stream.hpp"

namespace {
void require(bool ok) {
  if (!ok) std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  sinu::drivers::NmeaStream stream(size > 0 && (data[0] & 1));
  sinu::drivers::GpsFix fix;
  std::uint64_t framed = 0;
  auto check_fix = [](const sinu::drivers::GpsFix& f) {
    if (f.lat_deg) require(*f.lat_deg >= -90.0 && *f.lat_deg <= 90.0);
    if (f.lon_deg) require(*f.lon_deg >= -180.0 && *f.lon_deg <= 180.0);
    require(f.utc_ms >= 0 && f.utc_ms < 86'402'000);
  };
  for (char c : bytes) {
    if (stream.push(c, 1.0, fix)) check_fix(fix);
    if (stream.sentence_ready()) {
      ++framed;
      require(stream.last_sentence().size() <= sinu::drivers::kNmeaMaxSentence);
      require(stream.last_sentence().front() == '$');
    }
  }
  while (true) {
    const bool got = stream.finish(2.0, fix);
    if (stream.sentence_ready()) ++framed;
    if (!got) break;
    check_fix(fix);
  }
  const auto c = stream.counters();
  require(c.sentences.total() - c.framing.too_long == framed);  // every framed sentence is counted once

  sinu::drivers::NmeaParser parser;
  sinu::drivers::NmeaMessage msg;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= bytes.size(); ++i) {
    if (i == bytes.size() || bytes[i] == '\n') {
      parser.parse(bytes.substr(start, i - start), msg);
      start = i + 1;
    }
  }
  return 0;
}
