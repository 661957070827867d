#include "firmware/board/config/toml_reader.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdio>

namespace sinu::board {

namespace {

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string integer_text(std::int64_t v, bool hex) {
  char buf[32];
  if (hex) std::snprintf(buf, sizeof buf, "0x%02" PRIx64, static_cast<std::uint64_t>(v));
  else std::snprintf(buf, sizeof buf, "%" PRId64, v);
  return buf;
}

/// The value as a message quotes it: "text", 70000, 8.5, true, or its kind.
std::string describe(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "\"" + n.as_string()->get() + "\"";
    case toml::node_type::integer: return integer_text(n.as_integer()->get(), false);
    case toml::node_type::floating_point: return number_text(n.as_floating_point()->get());
    case toml::node_type::boolean: return n.as_boolean()->get() ? "true" : "false";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
  }
}

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

}  // namespace

// ---- TomlSection ----

TomlSection::TomlSection(TomlReader& reader, std::string path, const toml::table* table)
    : reader_(reader), path_(std::move(path)), table_(table) {}

const toml::node* TomlSection::find(std::string_view key, bool has_default) {
  const std::string p = key_path(key);
  if (reader_.key_paths_.insert(p).second) reader_.keys_.push_back({p, has_default});
  return table_ ? table_->get(key) : nullptr;
}

void TomlSection::fail(std::string_view key, const std::string& message) {
  const toml::node* n = table_ ? table_->get(key) : nullptr;
  reader_.error(n ? n->source() : table_ ? table_->source() : toml::source_region{}, key_path(key), message);
}

void TomlSection::text(std::string_view key, std::string& out, const TextCheck& check) {
  const toml::node* n = find(key, true);
  if (!n) return;
  if (!n->is_string()) return fail(key, "must be a string, not " + describe(*n));
  const std::string v = n->as_string()->get();
  if (check) {
    if (const std::string why = check(v); !why.empty()) return fail(key, why);
  }
  out = v;
}

void TomlSection::optional_text(std::string_view key, std::string& out, const TextCheck& check) {
  find(key, false);
  text(key, out, check);
}

void TomlSection::choice(std::string_view key, std::string& out, std::span<const std::string_view> allowed) {
  text(key, out, [allowed](const std::string& v) -> std::string {
    std::vector<std::string> names;
    for (auto a : allowed) {
      if (v == a) return "";
      names.emplace_back(a);
    }
    return "must be one of " + join(names) + ", not \"" + v + "\"";
  });
}

void TomlSection::flag(std::string_view key, bool& out) {
  const toml::node* n = find(key, true);
  if (!n) return;
  if (!n->is_boolean()) return fail(key, "must be true or false, not " + describe(*n));
  out = n->as_boolean()->get();
}

void TomlSection::number(std::string_view key, double& out, double lo, double hi) {
  std::optional<double> v = out;
  optional_number(key, v, lo, hi);
  out = *v;
}

void TomlSection::optional_number(std::string_view key, std::optional<double>& out, double lo, double hi) {
  const toml::node* n = find(key, out.has_value());
  if (!n) return;
  if (!n->is_number()) return fail(key, "must be a number, not " + describe(*n));
  const double v = n->value<double>().value_or(0.0);
  if (!(v >= lo && v <= hi)) return fail(key, "must be " + number_text(lo) + ".." + number_text(hi) + ", not " + describe(*n));
  out = v;
}

void TomlSection::text_list(std::string_view key, std::vector<std::string>& out, const TextCheck& check) {
  const toml::node* n = find(key, true);
  if (!n) return;
  if (!n->is_array()) return fail(key, "must be an array of strings, not " + describe(*n));
  std::vector<std::string> items;
  bool good = true;
  const toml::array& a = *n->as_array();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string item_path = key_path(key) + "[" + std::to_string(i) + "]";
    const toml::node& e = a[i];
    std::string why = e.is_string() ? (check ? check(e.as_string()->get()) : "") : "must be a string, not " + describe(e);
    if (!why.empty()) {
      reader_.error(e.source(), item_path, why);
      good = false;
    } else {
      items.push_back(e.as_string()->get());
    }
  }
  if (good) out = std::move(items);
}

bool TomlSection::read_integer(std::string_view key, std::int64_t& out, std::int64_t lo, std::int64_t hi,
                               std::span<const std::int64_t> allowed, bool hex) {
  const toml::node* n = find(key, true);
  if (!n) return false;
  if (!n->is_integer()) return fail(key, "must be an integer, not " + describe(*n)), false;
  const std::int64_t v = n->as_integer()->get();
  if (!allowed.empty()) {
    std::vector<std::string> names;
    for (auto a : allowed) names.push_back(integer_text(a, hex));
    if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
      return fail(key, "must be one of " + join(names) + ", not " + integer_text(v, hex)), false;
  } else if (v < lo || v > hi) {
    return fail(key, "must be " + integer_text(lo, hex) + ".." + integer_text(hi, hex) + ", not " + integer_text(v, hex)),
           false;
  }
  out = v;
  return true;
}

// ---- TomlReader ----

TomlSection TomlReader::section(const std::string& path) {
  if (std::find(sections_.begin(), sections_.end(), path) == sections_.end()) sections_.push_back(path);
  const toml::table* t = &root_;
  std::string so_far;
  for (std::size_t start = 0; start <= path.size();) {
    const std::size_t dot = std::min(path.find('.', start), path.size());
    const std::string part = path.substr(start, dot - start);
    so_far += (so_far.empty() ? "" : ".") + part;
    const toml::node* n = t->get(part);
    if (!n) return {*this, path, nullptr};
    if (!n->is_table()) {
      if (not_tables_.insert(so_far).second)
        error(n->source(), so_far, "must be a section ([" + so_far + "]), not " + describe(*n));
      return {*this, path, nullptr};
    }
    t = n->as_table();
    start = dot + 1;
  }
  return {*this, path, t};
}

bool TomlReader::is_section_or_parent(const std::string& path) const {
  for (const auto& s : sections_)
    if (s == path || s.rfind(path + ".", 0) == 0) return true;
  return false;
}

std::string TomlReader::known_keys_of(const std::string& section) const {
  std::vector<std::string> names;
  for (const auto& k : keys_)
    if (k.path.rfind(section + ".", 0) == 0) names.push_back(k.path.substr(section.size() + 1));
  return join(names);
}

void TomlReader::walk(const toml::table& table, const std::string& prefix) {
  for (auto&& [k, v] : table) {
    const std::string path = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (key_paths_.count(path)) continue;  // read (and checked) by the schema
    if (is_section_or_parent(path)) {
      if (v.is_table()) walk(*v.as_table(), path);
      continue;  // not a table: reported by section()
    }
    if (v.is_table())
      error(k.source(), path, "unknown section (sections: " + join(sections_) + ")");
    else if (!prefix.empty() && std::find(sections_.begin(), sections_.end(), prefix) != sections_.end())
      error(k.source(), path, "unknown key ([" + prefix + "] has " + known_keys_of(prefix) + ")");
    else
      error(k.source(), path, "unknown key (keys belong in the sections " + join(sections_) + ")");
  }
}

void TomlReader::check_unknown() { walk(root_, ""); }

void TomlReader::error(const toml::source_region& where, const std::string& path, const std::string& message) {
  errors_.push_back({where.begin.line, where.begin.column, path + ": " + message});
}

std::string TomlReader::errors() const {
  std::vector<Error> sorted = errors_;
  std::stable_sort(sorted.begin(), sorted.end(), [](const Error& a, const Error& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  std::string s;
  for (const auto& e : sorted) {
    if (!s.empty()) s += '\n';
    s += file_;
    if (e.line > 0) s.append(":").append(std::to_string(e.line));
    s.append(": ").append(e.text);
  }
  return s;
}

}  // namespace sinu::board
