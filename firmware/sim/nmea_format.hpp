#pragma once
// NMEA 0183 sentence text for the simulated receiver, written into a caller's
// buffer (no allocation). Corruption for robustness tests: a corrupted
// sentence ALWAYS fails framing/checksum validation (a character between '$'
// and '*' replaced by a different one, the sentence cut before its '*', or a
// line of garbage without '$'), so a reader can tell it from a good one.
#include <cstddef>
#include <span>
#include <string_view>

#include "firmware/sim/rng.hpp"

namespace sinu::sim {

inline constexpr std::size_t kSentenceBuffer = 192;

/// Appends "*hh" (XOR of the bytes between '$' and '*') to buf[0..len).
std::size_t append_checksum(std::span<char> buf, std::size_t len);
/// "ddmm.mmmmmm" (lat, 2 degree digits) or "dddmm.mmmmmm" (lon) and hemisphere.
std::size_t format_angle(std::span<char> buf, double deg, int degree_digits, char positive, char negative);
/// "hhmmss.ss" from UTC seconds of the day.
std::size_t format_utc(std::span<char> buf, double utc_s_of_day);
/// Corrupts the sentence in place; returns its new length.
std::size_t corrupt_sentence(std::span<char> buf, std::size_t len, Rng& rng);

}  // namespace sinu::sim
