#pragma once
// NMEA latitude/longitude fields, "ddmm.mmmm" / "dddmm.mmmm" plus a
// hemisphere letter, read and written back with the same number of minute
// decimals. Altitude-like plain decimals ("45.300") likewise.
#include <optional>
#include <string>
#include <string_view>

namespace sinu::test::faults {

struct AngleFormat {
  int degree_digits;        // 2 for latitude, 3 for longitude
  char positive, negative;  // 'N','S' or 'E','W'
};
inline constexpr AngleFormat kLatitude{2, 'N', 'S'};
inline constexpr AngleFormat kLongitude{3, 'E', 'W'};

/// A field's value and how many decimals it was written with.
struct DecimalValue {
  double value = 0.0;  // signed degrees for an angle
  int decimals = 0;
};

/// Reads "ddmm.mmmm" + hemisphere; nullopt unless exactly degree_digits + 2
/// integer digits, optional decimals, minutes < 60 and a known letter.
std::optional<DecimalValue> parse_angle(std::string_view field, std::string_view hemisphere, AngleFormat f);
/// Writes signed degrees with `decimals` minute decimals (rounded, carrying
/// 60 minutes into the degrees); the letter follows the sign (a value that
/// rounds to zero is positive).
void format_angle(double deg, int decimals, AngleFormat f, std::string& field, std::string& hemisphere);

/// Reads "[+-]digits[.digits]"; nullopt for any other form.
std::optional<DecimalValue> parse_plain_decimal(std::string_view field);
/// "%.*f", without a "-" on a value that rounds to zero.
std::string format_plain_decimal(double value, int decimals);

}  // namespace sinu::test::faults
