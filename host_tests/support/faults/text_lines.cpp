#include "host_tests/support/faults/text_lines.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sinu::test::faults {

TextLines split_lines(std::string_view bytes) {
  TextLines lines;
  std::size_t begin = 0;
  while (begin < bytes.size()) {
    const std::size_t lf = bytes.find('\n', begin);
    if (lf == std::string_view::npos) {  // last line, no terminator
      lines.push_back({std::string(bytes.substr(begin)), ""});
      break;
    }
    const bool crlf = lf > begin && bytes[lf - 1] == '\r';
    const std::size_t end = crlf ? lf - 1 : lf;
    lines.push_back({std::string(bytes.substr(begin, end - begin)), crlf ? "\r\n" : "\n"});
    begin = lf + 1;
  }
  return lines;
}

std::string join_lines(const TextLines& lines) {
  std::string out;
  for (const auto& l : lines) out += l.text + l.eol;
  return out;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_bytes(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

std::optional<double> leading_number(std::string_view line) {
  const std::string prefix(line.substr(0, line.find(',')));
  if (prefix.empty()) return std::nullopt;
  char* end = nullptr;
  const double t = std::strtod(prefix.c_str(), &end);
  if (end != prefix.c_str() + prefix.size() || !std::isfinite(t)) return std::nullopt;
  return t;
}

std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = line.find(',', begin);
    fields.emplace_back(line.substr(begin, comma == std::string_view::npos ? std::string_view::npos : comma - begin));
    if (comma == std::string_view::npos) return fields;
    begin = comma + 1;
  }
}

std::string join_fields(const std::vector<std::string>& fields) {
  std::string out;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) out += ',';
    out += fields[i];
  }
  return out;
}

}  // namespace sinu::test::faults
