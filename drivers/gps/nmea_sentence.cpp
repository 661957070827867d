#include "drivers/gps/nmea_sentence.hpp"

namespace sinu::drivers {

namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

bool is_upper_alnum(char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); }

}  // namespace

const char* to_string(SentenceCheck c) {
  switch (c) {
    case SentenceCheck::Ok: return "ok";
    case SentenceCheck::NoDollar: return "does not start with '$'";
    case SentenceCheck::TooLong: return "sentence too long";
    case SentenceCheck::MissingChecksum: return "missing checksum";
    case SentenceCheck::BadChecksum: return "checksum mismatch";
    case SentenceCheck::BadCharacter: return "non-printable character";
    case SentenceCheck::BadAddress: return "bad address field";
  }
  return "unknown";
}

SentenceCheck check_sentence(std::string_view s) {
  if (s.empty() || s.front() != '$') return SentenceCheck::NoDollar;
  if (s.size() > kNmeaMaxSentence) return SentenceCheck::TooLong;
  const std::size_t star = s.rfind('*');
  if (star == std::string_view::npos || star + 3 != s.size()) return SentenceCheck::MissingChecksum;
  unsigned sum = 0;
  for (std::size_t i = 1; i < star; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c > 0x7e || c == '$' || c == '*') return SentenceCheck::BadCharacter;
    sum ^= c;
  }
  const int hi = hex_value(s[star + 1]);
  const int lo = hex_value(s[star + 2]);
  if (hi < 0 || lo < 0) return SentenceCheck::BadChecksum;
  if (static_cast<unsigned>(hi * 16 + lo) != sum) return SentenceCheck::BadChecksum;
  const std::size_t comma = s.find(',');
  const std::size_t addr_end = comma == std::string_view::npos ? star : comma;
  const std::string_view addr = s.substr(1, addr_end - 1);
  if (addr.size() < 2) return SentenceCheck::BadAddress;
  for (char c : addr)
    if (!is_upper_alnum(c)) return SentenceCheck::BadAddress;
  // Standard addresses are TTSSS; proprietary ones start with 'P'. Some
  // receivers send longer non-standard ones (Unicore $SNRSTAT, $GYOACC): they
  // and proprietary ones of any length ($PSTMANTENNASTATUS) are
  // well-framed sentences of a type we do not decode, not corruption.
  if (addr.front() != 'P' && addr.size() > kNmeaMaxAddress) return SentenceCheck::BadAddress;
  return SentenceCheck::Ok;
}

NmeaFields split_fields(std::string_view s) {
  NmeaFields out;
  const std::size_t star = s.rfind('*');
  std::string_view body = s.substr(1, (star == std::string_view::npos ? s.size() : star) - 1);
  while (true) {
    const std::size_t comma = body.find(',');
    const std::string_view f = body.substr(0, comma);
    if (out.count == kNmeaMaxFields) {
      out.overflow = true;
      break;
    }
    out.field[out.count++] = f;
    if (comma == std::string_view::npos) break;
    body.remove_prefix(comma + 1);
  }
  return out;
}

NmeaAddress split_address(std::string_view address) {
  if (!address.empty() && address.front() == 'P') return {address.substr(0, 1), address.substr(1)};
  if (address.size() < 2) return {address, {}};
  return {address.substr(0, 2), address.substr(2)};
}

}  // namespace sinu::drivers
