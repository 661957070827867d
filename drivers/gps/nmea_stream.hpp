#pragma once
// NMEA bytes -> GPS fixes: NmeaLexer (framing) -> NmeaParser (checksum,
// fields) -> FixAssembler (epochs). One object per serial line or capture.
#include <cstdint>
#include <string_view>

#include "drivers/gps/fix_assembler.hpp"
#include "drivers/gps/nmea_lexer.hpp"
#include "drivers/gps/nmea_parser.hpp"

namespace sinu::drivers {

struct NmeaStreamCounters {
  NmeaCounters sentences;     // parser counters; too_long includes the lexer's
  NmeaLexerCounters framing;  // what the lexer dropped between sentences
  std::uint64_t fixes = 0;    // epochs emitted
  std::uint64_t late_sentences = 0;  // after their epoch was emitted (FixAssembler)
};

class NmeaStream {
 public:
  explicit NmeaStream(bool comments = false) : lexer_(comments) {}
  /// Feeds one byte that arrived at `arrival_s`. Returns true and fills `fix`
  /// when an epoch completed. After each completed sentence, sentence_ready()
  /// is true and last_sentence() holds it (for logging to gps.nmea).
  bool push(char byte, double arrival_s, GpsFix& fix);
  /// End of stream: the last open sentence and epoch.
  bool finish(double arrival_s, GpsFix& fix);
  bool sentence_ready() const { return sentence_ready_; }
  std::string_view last_sentence() const { return lexer_.sentence(); }
  NmeaStreamCounters counters() const;
  const NmeaParser& parser() const { return parser_; }

 private:
  bool handle_sentence(double arrival_s, GpsFix& fix);

  NmeaLexer lexer_;
  NmeaParser parser_;
  FixAssembler assembler_;
  bool sentence_ready_ = false;
  bool flushed_ = false;
};

}  // namespace sinu::drivers
