#pragma once
// Reads a parsed TOML document against a schema written as code: the schema
// asks each section for its keys by name, type and range, and the reader
// keeps what it finds. Keys never asked for are unknown. Every problem is
// collected as "FILE:LINE: dotted.key: what is wrong", in the file's order,
// with the line from toml++'s source regions.
#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <toml++/toml.h>
#include <vector>

#include "firmware/board/config/config_key.hpp"

namespace sinu::board {

/// Checks a string value; returns what is wrong with it, or "" if nothing.
using TextCheck = std::function<std::string(const std::string&)>;

class TomlReader;

/// One [section] of the document (absent sections read as empty).
class TomlSection {
 public:
  TomlSection(TomlReader& reader, std::string path, const toml::table* table);
  const std::string& path() const { return path_; }

  void text(std::string_view key, std::string& out, const TextCheck& check = {});
  /// A string without a default (empty when absent).
  void optional_text(std::string_view key, std::string& out, const TextCheck& check = {});
  void choice(std::string_view key, std::string& out, std::span<const std::string_view> allowed);
  void flag(std::string_view key, bool& out);
  void number(std::string_view key, double& out, double lo, double hi);
  void optional_number(std::string_view key, std::optional<double>& out, double lo, double hi);
  void text_list(std::string_view key, std::vector<std::string>& out, const TextCheck& check);
  template <class Int>
  void integer(std::string_view key, Int& out, std::int64_t lo, std::int64_t hi) {
    std::int64_t v = static_cast<std::int64_t>(out);
    if (read_integer(key, v, lo, hi, {}, false)) out = static_cast<Int>(v);
  }
  /// An integer that must be one of `allowed` (written in hex in messages when `hex`).
  template <class Int>
  void integer_of(std::string_view key, Int& out, std::span<const std::int64_t> allowed, bool hex = false) {
    std::int64_t v = static_cast<std::int64_t>(out);
    if (read_integer(key, v, 0, 0, allowed, hex)) out = static_cast<Int>(v);
  }
  /// Reports `message` for `key`: at its line, or the section's when it is absent.
  void fail(std::string_view key, const std::string& message);

 private:
  const toml::node* find(std::string_view key, bool has_default);
  bool read_integer(std::string_view key, std::int64_t& out, std::int64_t lo, std::int64_t hi,
                    std::span<const std::int64_t> allowed, bool hex);
  std::string key_path(std::string_view key) const { return path_ + "." + std::string(key); }

  TomlReader& reader_;
  std::string path_;
  const toml::table* table_;
};

class TomlReader {
 public:
  TomlReader(std::string file, const toml::table& root) : file_(std::move(file)), root_(root) {}
  /// The section at a dotted path ("outputs.nmea"); a value there that is not
  /// a table is an error, and the section then reads as empty.
  TomlSection section(const std::string& path);
  /// Reports every key and section of the document the schema never asked for.
  void check_unknown();
  void error(const toml::source_region& where, const std::string& path, const std::string& message);
  bool ok() const { return errors_.empty(); }
  /// All errors, one per line, in the order of the file.
  std::string errors() const;
  const std::vector<ConfigKey>& keys() const { return keys_; }

 private:
  friend class TomlSection;
  struct Error {
    std::uint32_t line = 0, column = 0;
    std::string text;
  };
  void walk(const toml::table& table, const std::string& prefix);
  std::string known_keys_of(const std::string& section) const;
  bool is_section_or_parent(const std::string& path) const;

  std::string file_;
  const toml::table& root_;
  std::vector<ConfigKey> keys_;
  std::set<std::string> key_paths_;
  std::vector<std::string> sections_;
  std::set<std::string> not_tables_;  // section paths already reported as not a table
  std::vector<Error> errors_;
};

}  // namespace sinu::board
