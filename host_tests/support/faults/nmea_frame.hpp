#pragma once
// NMEA 0183 framing for the fault injector, written here rather than taken
// from drivers/gps so the tests check the injector against an independent
// reader: "$" body "*" hh, hh the XOR of the body's bytes in hex.
#include <optional>
#include <string>
#include <string_view>

namespace sinu::test::faults {

/// XOR of all bytes of `body`.
unsigned char nmea_xor(std::string_view body);

/// The body of a sentence a receiver would accept: '$', printable bytes
/// without '$' or '*', '*', two hex digits (either case) equal to the XOR.
/// nullopt for anything else.
std::optional<std::string_view> checked_body(std::string_view sentence);

/// True if the sentence's checksum digits are lower case hex ("*6a").
bool lower_case_checksum(std::string_view sentence);

/// "$" + body + "*" + the XOR in two hex digits.
std::string frame_sentence(std::string_view body, bool lower_case_hex);
/// "$" + body + "*" + `checksum` in two hex digits, whatever the body's XOR.
std::string frame_with_checksum(std::string_view body, unsigned char checksum, bool lower_case_hex);

}  // namespace sinu::test::faults
