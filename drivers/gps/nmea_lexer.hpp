#pragma once
// NMEA 0183 from a byte stream (a serial port, a gpsd capture): finds the
// sentences "$...*hh" among whatever else the line carries. Bounded buffer,
// no allocation. Recovery rules (docs/nmea.md):
//   - a '$' inside a sentence starts a new one; the interrupted part is kept
//     aside and, if the line right after the intruder's CR LF continues
//     without a '$', resumed (a receiver injecting a sentence into another,
//     as gpsd's isync capture shows). The checksum judges the result. A '$'
//     right after the intruder drops the kept part ("$$" and truncations);
//   - a control byte (NUL, other garbage below 0x20 or above 0x7e) inside a
//     sentence abandons it; outside a sentence every non-'$' byte is noise;
//   - a sentence longer than kNmeaMaxSentence is abandoned and counted;
//   - CR or LF ends a sentence (receivers that send bare LF are accepted);
//   - optionally, a line starting with '#' is a comment (gpsd's test logs).
// The lexer only frames: checksum and fields are the parser's to judge.
#include <array>
#include <cstdint>
#include <string_view>

#include "drivers/gps/nmea_sentence.hpp"

namespace sinu::drivers {

struct NmeaLexerCounters {
  std::uint64_t sentences = 0;     // framed sentences handed on
  std::uint64_t too_long = 0;      // abandoned: longer than kNmeaMaxSentence
  std::uint64_t interrupted = 0;   // abandoned: a '$' or a control byte arrived inside
  std::uint64_t resumed = 0;       // interrupted by another sentence, then completed
  std::uint64_t noise_bytes = 0;   // bytes outside any sentence (not CR/LF, not comments)
  std::uint64_t comment_lines = 0; // '#' lines skipped (comment mode only)
};

class NmeaLexer {
 public:
  /// `comments`: treat a '#' at the start of a line as a comment to the end of the line.
  explicit NmeaLexer(bool comments = false) : comments_(comments) {}
  /// Feeds one byte. Returns true when it completed a sentence; sentence()
  /// holds it (without CR LF) until the next call.
  bool push(char byte);
  /// End of stream: a sentence still open has no terminator; it is handed on
  /// if it looks complete (ends in "*hh"), otherwise counted as interrupted.
  bool finish();
  std::string_view sentence() const { return {buffer_.data(), length_}; }
  const NmeaLexerCounters& counters() const { return counters_; }

 private:
  enum class State { LineStart, Between, InSentence, TooLong, Comment, AfterIntruder };
  bool complete();
  void start_sentence();
  bool after_intruder(char byte);
  void drop_kept();

  std::array<char, kNmeaMaxSentence> buffer_{};
  std::size_t length_ = 0;
  std::array<char, kNmeaMaxSentence> kept_{};  // the sentence an intruder interrupted
  std::size_t kept_length_ = 0;
  State state_ = State::LineStart;
  bool comments_;
  NmeaLexerCounters counters_;
};

}  // namespace sinu::drivers
