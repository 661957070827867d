#pragma once
// NMEA 0183 sentence text for the simulated receiver, written into a caller's
// buffer (no allocation). Corruption for robustness tests: a corrupted
// sentence ALWAYS fails framing/checksum validation (a character between '$'
// and '*' replaced by a different one, the sentence cut before its '*', or a
// line of garbage without '$'), so a reader can tell it from a good one.
// Checksum and field text are the program's one NMEA writer toolkit
// (firmware/board/outputs/nmea_text), shared with the navigation unit's output.
#include <cstddef>
#include <span>
#include <string_view>

#include "firmware/board/outputs/nmea_text.hpp"
#include "firmware/host/sim/rng.hpp"

namespace sinu::sim {

inline constexpr std::size_t kSentenceBuffer = 192;

using board::append_checksum;
using board::format_angle;
using board::written_length;
/// "hhmmss.ss" from UTC seconds of the day (rounded to the hundredth).
std::size_t format_utc(std::span<char> buf, double utc_s_of_day);
/// Corrupts the sentence in place; returns its new length.
std::size_t corrupt_sentence(std::span<char> buf, std::size_t len, Rng& rng);

}  // namespace sinu::sim
