#pragma once
// A text file as lines that remember their own terminator, so a fault can
// change or drop lines and write the rest back byte for byte: LF, CR LF, or
// nothing (a last line without LF) stays what it was.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sinu::test::faults {

struct TextLine {
  std::string text;  // without the terminator
  std::string eol;   // "\n", "\r\n" or "" (last line of a file without a final LF)
};

using TextLines = std::vector<TextLine>;

/// Splits bytes on LF; a CR right before the LF belongs to the terminator.
TextLines split_lines(std::string_view bytes);
std::string join_lines(const TextLines& lines);

/// The whole file (throws std::runtime_error if it cannot be read).
std::string read_bytes(const std::filesystem::path& path);
/// Creates or replaces the file (throws std::runtime_error on failure).
void write_bytes(const std::filesystem::path& path, std::string_view bytes);

/// The number before the line's first comma, read as strtod would (the
/// whole text must be consumed): a CSV row's `t` or a gps.nmea arrival time.
/// nullopt for a header, an empty line or an unreadable prefix.
std::optional<double> leading_number(std::string_view line);

/// Comma-separated fields of a CSV row, and back.
std::vector<std::string> split_fields(std::string_view line);
std::string join_fields(const std::vector<std::string>& fields);

}  // namespace sinu::test::faults
