#include "drivers/gps/nmea_lexer.hpp"

#include <algorithm>

namespace sinu::drivers {

namespace {
bool is_line_end(char c) { return c == '\r' || c == '\n'; }
bool is_printable(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u >= 0x20 && u <= 0x7e;
}
}  // namespace

void NmeaLexer::drop_kept() {
  if (kept_length_ == 0) return;
  ++counters_.interrupted;
  kept_length_ = 0;
}

void NmeaLexer::start_sentence() {
  buffer_[0] = '$';
  length_ = 1;
  state_ = State::InSentence;
}

bool NmeaLexer::complete() {
  state_ = kept_length_ > 0 ? State::AfterIntruder : State::LineStart;
  if (length_ <= 1) {  // a lone '$' at the end of a line
    ++counters_.interrupted;
    length_ = 0;
    return false;
  }
  ++counters_.sentences;
  return true;
}

bool NmeaLexer::push(char c) {
  switch (state_) {
    case State::InSentence:
      if (is_line_end(c)) return complete();
      if (c == '$') {
        if (length_ > 1) {  // "$$" is a plain restart; anything longer is kept aside
          drop_kept();
          kept_length_ = length_;
          std::copy_n(buffer_.begin(), length_, kept_.begin());
        }
        start_sentence();
        return false;
      }
      if (!is_printable(c)) {
        drop_kept();
        ++counters_.interrupted;
        ++counters_.noise_bytes;
        length_ = 0;
        state_ = State::Between;
        return false;
      }
      if (length_ == buffer_.size()) {
        drop_kept();
        ++counters_.too_long;
        length_ = 0;
        state_ = State::TooLong;
        return false;
      }
      buffer_[length_++] = c;
      return false;
    case State::TooLong:  // skip to the next line end or '$'
      if (c == '$') start_sentence();
      else if (is_line_end(c)) state_ = State::LineStart;
      return false;
    case State::AfterIntruder:
      return after_intruder(c);
    case State::Comment:
      if (c == '\n') state_ = State::LineStart;
      return false;
    case State::LineStart:
      if (comments_ && c == '#') {
        ++counters_.comment_lines;
        state_ = State::Comment;
        return false;
      }
      [[fallthrough]];
    case State::Between:
      if (c == '$') start_sentence();
      else if (is_line_end(c)) state_ = State::LineStart;
      else {
        ++counters_.noise_bytes;
        state_ = State::Between;
      }
      return false;
  }
  return false;
}

bool NmeaLexer::after_intruder(char c) {
  if (is_line_end(c)) return false;  // the intruder's CR LF
  if (is_printable(c) && c != '$' && !(comments_ && c == '#')) {
    std::copy_n(kept_.begin(), kept_length_, buffer_.begin());
    length_ = kept_length_;
    kept_length_ = 0;
    ++counters_.resumed;
    state_ = State::InSentence;
    return push(c);
  }
  drop_kept();  // the interrupted sentence is not continued
  state_ = State::LineStart;
  return push(c);
}

bool NmeaLexer::finish() {
  drop_kept();
  if (state_ != State::InSentence) return false;
  const std::string_view s = sentence();
  if (s.size() >= 4 && s[s.size() - 3] == '*') return complete();
  ++counters_.interrupted;
  length_ = 0;
  state_ = State::LineStart;
  return false;
}

}  // namespace sinu::drivers
