#pragma once
// NMEA 0183 field text shared by every writer of sentences in the program:
// the simulator's receiver (firmware/host/sim/gps_receiver) and the navigation
// unit's NMEA output (nmea_sentences). Everything is written into a caller's
// buffer with snprintf: no allocation.
#include <cstddef>
#include <span>

namespace sinu::board {

/// Characters snprintf put into a buffer of `capacity` given its return value.
std::size_t written_length(int n, std::size_t capacity);
/// Appends "*hh" (XOR of the bytes between '$' and '*', upper-case hex) and a
/// NUL to buf[0..len); buf must hold len + 4 characters. Returns len + 3.
std::size_t append_checksum(std::span<char> buf, std::size_t len);
/// "ddmm.mmmmmm" (lat, 2 degree digits) or "dddmm.mmmmmm" (lon), a comma and
/// the hemisphere letter. Six decimals of a minute: 1.85 mm of latitude.
std::size_t format_angle(std::span<char> buf, double deg, int degree_digits, char positive, char negative);
/// "hhmmss" and, for decimals 1..3, "." and that many digits of a second, from
/// a count of 10^-decimals s since midnight (0 .. 86'400 s).
std::size_t format_time_of_day(std::span<char> buf, long long ticks_of_day, int decimals);
/// `value` with `decimals` digits after the point, or nothing (an empty NMEA
/// field: "not available") if it is not finite or |value| > max_abs, so that
/// a diverged number can never overflow a sentence.
std::size_t format_fixed(std::span<char> buf, double value, int decimals, double max_abs);

}  // namespace sinu::board
