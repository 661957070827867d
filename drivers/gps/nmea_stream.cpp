#include "drivers/gps/nmea_stream.hpp"

namespace sinu::drivers {

bool NmeaStream::handle_sentence(double arrival_s, GpsFix& fix) {
  sentence_ready_ = true;
  NmeaMessage msg;
  if (parser_.parse(lexer_.sentence(), msg) != ParseResult::Message) return false;
  return assembler_.add(msg, arrival_s, fix);
}

bool NmeaStream::push(char byte, double arrival_s, GpsFix& fix) {
  sentence_ready_ = false;
  if (!lexer_.push(byte)) return false;
  return handle_sentence(arrival_s, fix);
}

bool NmeaStream::finish(double arrival_s, GpsFix& fix) {
  sentence_ready_ = false;
  if (lexer_.finish() && handle_sentence(arrival_s, fix)) return true;  // the flush follows on the next call
  if (flushed_) return false;
  flushed_ = true;
  return assembler_.flush(fix);
}

NmeaStreamCounters NmeaStream::counters() const {
  NmeaStreamCounters c;
  c.sentences = parser_.counters();
  c.sentences.too_long += lexer_.counters().too_long;
  c.framing = lexer_.counters();
  c.fixes = assembler_.epochs();
  c.late_sentences = assembler_.late_sentences();
  return c;
}

}  // namespace sinu::drivers
