#pragma once
// Garbage a GNSS receiver's serial line produces when it is noisy, one
// sentence at a time (GnssGarbage in dataset_faults.hpp lists the kinds).
// Every result fails NMEA framing or checksum validation by construction:
//  - a sentence holding any byte outside 0x20..0x7E is rejected (at index 0
//    it is not '$'; between '$' and '*' it is a bad character; the two bytes
//    after '*' must be hex digits);
//  - a sentence without '*' has no checksum;
//  - "$" body "*hh" with hh != XOR(body) and no other '*' fails the checksum.
#include <cstdint>
#include <random>
#include <string>
#include <string_view>

namespace sinu::test::faults {

inline constexpr std::size_t kMaxGarbageBytes = 250;

class GarbageGenerator {
 public:
  explicit GarbageGenerator(std::uint64_t seed) : rng_(seed) {}
  /// Garbage to stand in for `original` (the sentence it replaces).
  std::string next(std::string_view original);

 private:
  std::uint64_t below(std::uint64_t n) { return rng_() % n; }  // bias < 2^-50 for our n
  char random_byte();                                          // 0x00..0xFF except LF and CR
  char random_non_printable();                                 // control or high byte, except LF and CR
  std::string noise();
  std::string binary();
  std::string truncated(std::string_view original);
  std::string wrong_checksum(std::string_view original);
  void force_non_printable(std::string& s);

  std::mt19937_64 rng_;
};

}  // namespace sinu::test::faults
