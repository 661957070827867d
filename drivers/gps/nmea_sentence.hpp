#pragma once
// One NMEA 0183 sentence: framing, checksum and field splitting.
// Works on a string_view of the sentence without CR LF, e.g.
//   "$GPGGA,101520.40,3024.51234,N,...,*6A"
// Nothing here allocates.
#include <array>
#include <cstddef>
#include <string_view>

namespace sinu::drivers {

/// Longest sentence accepted, '$' to checksum inclusive. NMEA 0183 says 82
/// with CR LF; real receivers exceed it (MediaTek $PMTKCHN is 206 bytes in
/// gpsd's mtk-3301 capture, u-blox GSV with signal IDs, Trimble), so we allow more.
inline constexpr std::size_t kNmeaMaxSentence = 255;
/// Longest address field ("GPGGA" is 5; vendor extensions reach 7).
inline constexpr std::size_t kNmeaMaxAddress = 10;
/// Most fields any sentence we decode has (GSA has 18 after the address).
inline constexpr std::size_t kNmeaMaxFields = 32;

enum class SentenceCheck {
  Ok,
  NoDollar,          // does not start with '$'
  TooLong,           // longer than kNmeaMaxSentence
  MissingChecksum,   // no "*hh" at the end (truncated sentence)
  BadChecksum,       // "*hh" present but does not match
  BadCharacter,      // non-printable byte inside the sentence
  BadAddress,        // address field is not TTSSS or Pxxx
};

const char* to_string(SentenceCheck c);

/// Validates framing and checksum (hex digits of either case).
SentenceCheck check_sentence(std::string_view sentence);

/// Fields of a validated sentence: fields[0] is the address ("GPGGA"),
/// fields[1..] the data fields; the checksum is not a field.
struct NmeaFields {
  std::array<std::string_view, kNmeaMaxFields> field{};
  std::size_t count = 0;
  bool overflow = false;  // more fields than kNmeaMaxFields
  std::string_view operator[](std::size_t i) const { return i < count ? field[i] : std::string_view{}; }
};

/// Splits "$ADDR,f1,f2*hh" into {ADDR, f1, f2}. Assumes check_sentence() == Ok.
NmeaFields split_fields(std::string_view sentence);

/// Talker ("GP", "GN", ..., or "P" for proprietary) and sentence type ("GGA").
struct NmeaAddress {
  std::string_view talker;
  std::string_view type;
};
NmeaAddress split_address(std::string_view address);

}  // namespace sinu::drivers
