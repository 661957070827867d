#include "firmware/host/dataset/csv_table.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace sinu::dataset {

namespace {

constexpr std::size_t kWriteBuffer = 256 * 1024;
constexpr std::size_t kMaxRowChars = kMaxCsvColumns * 40;  // one formatted row fits easily

std::string quoted(std::string_view s) {
  constexpr std::size_t kShown = 40;
  std::string out = "'";
  out += s.substr(0, kShown);
  if (s.size() > kShown) out += "...";
  return out + "'";
}

std::string header_of(const CsvSchema& schema) {
  std::string h;
  for (std::size_t i = 0; i < schema.columns.size(); ++i) {
    if (i) h += ',';
    h += schema.columns[i];
  }
  return h;
}

}  // namespace

void CsvRow::clear(std::size_t n_columns) {
  present = 0;
  for (std::size_t i = 0; i < n_columns; ++i) value[i] = std::numeric_limits<double>::quiet_NaN();
}

namespace {

/// Clinger's fast path (1990): when the decimal digits form an integer
/// mantissa below 2^53 and the power of ten is within [-22, 22], both are
/// exact doubles and m * 10^e (or m / 10^-e) is one correctly rounded IEEE
/// operation: the result equals strtod's. Anything else returns false and
/// takes the general path.
bool parse_decimal_fast(const char* p, const char* last, double& out) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  constexpr std::uint64_t kMaxExactMantissa = std::uint64_t{1} << 53;
  constexpr long kMaxDigits = 19;  // 10^19 < 2^64: the mantissa cannot overflow
  auto is_digit = [](char c) { return static_cast<unsigned>(c - '0') < 10u; };
  if (p == last) return false;
  const bool negative = *p == '-';
  if (negative) ++p;
  const char* const digits_begin = p;
  std::uint64_t mantissa = 0;
  for (; p != last && is_digit(*p); ++p) mantissa = mantissa * 10 + static_cast<std::uint64_t>(*p - '0');
  long digits = p - digits_begin;
  long exponent = 0;
  if (p != last && *p == '.') {
    const char* const frac_begin = ++p;
    for (; p != last && is_digit(*p); ++p) mantissa = mantissa * 10 + static_cast<std::uint64_t>(*p - '0');
    exponent = -(p - frac_begin);
    digits -= exponent;
  }
  if (digits == 0 || digits > kMaxDigits) return false;
  if (p != last && (*p == 'e' || *p == 'E')) {
    ++p;
    const bool exp_negative = p != last && *p == '-';
    if (p != last && (*p == '-' || *p == '+')) ++p;
    if (p == last) return false;
    long e = 0;
    for (; p != last && is_digit(*p) && e < 1000; ++p) e = e * 10 + (*p - '0');
    exponent += exp_negative ? -e : e;
  }
  if (p != last || mantissa > kMaxExactMantissa || exponent < -22 || exponent > 22) return false;
  const auto m = static_cast<double>(mantissa);
  const double v = exponent < 0 ? m / kPow10[-exponent] : m * kPow10[exponent];
  out = negative ? -v : v;
  return true;
}

}  // namespace

bool parse_double(std::string_view f, double& out) {
  const char* first = f.data();
  const char* last = f.data() + f.size();
  if (parse_decimal_fast(first, last, out)) return true;
  const auto [p, ec] = std::from_chars(first, last, out);
  if (ec == std::errc{} && p == last) return true;
  // Forms strtod accepts that from_chars does not: leading '+', leading
  // blanks, hexadecimal floats, out-of-range values (-> +-inf / 0).
  char buf[96];
  if (f.empty() || f.size() >= sizeof buf) return false;
  std::memcpy(buf, first, f.size());
  buf[f.size()] = '\0';
  char* end = nullptr;
  out = std::strtod(buf, &end);
  return end == buf + f.size();
}

CsvReader::CsvReader(const CsvSchema& schema, CsvLeniency leniency) : schema_(schema), leniency_(leniency) {}

void CsvReader::note_anomaly(std::size_t line, std::size_t column, const std::string& message) {
  if (first_anomaly_.message.empty()) first_anomaly_ = Diagnostic{path_, line, column, message};
}

ReadStatus CsvReader::fail(std::size_t line, std::size_t column, std::string message) {
  error_ = Diagnostic{path_, line, column, std::move(message)};
  return ReadStatus::Error;
}

bool CsvReader::open(const std::string& path) {
  path_ = path;
  rows_ = 0;
  first_t_count_ = 0;
  if (!lines_.open(path)) {
    fail(0, 0, std::string("cannot open: ") + std::strerror(errno));
    return false;
  }
  std::string_view line;
  const std::string expected = header_of(schema_);
  switch (lines_.next(line)) {
    case LineReader::Status::Line: break;
    case LineReader::Status::End: fail(0, 0, "empty file: expected the header '" + expected + "'"); return false;
    default: fail(1, 0, "cannot read the header line"); return false;
  }
  if (line.size() >= 3 && static_cast<unsigned char>(line[0]) == 0xEF) line.remove_prefix(3);  // UTF-8 BOM
  if (line != expected) {
    // Point at the first character that differs.
    std::size_t col = 0;
    while (col < line.size() && col < expected.size() && line[col] == expected[col]) ++col;
    fail(1, col + 1, "missing or wrong header: expected '" + expected + "', found " + quoted(line));
    return false;
  }
  return true;
}

ReadStatus CsvReader::next(CsvRow& row) {
  std::string_view line;
  switch (lines_.next(line)) {
    case LineReader::Status::Line: break;
    case LineReader::Status::End: return ReadStatus::End;
    case LineReader::Status::TooLong: return fail(lines_.line_number(), 0, "line too long");
    case LineReader::Status::IoError: return fail(lines_.line_number() + 1, 0, "read error");
  }
  const std::size_t n = schema_.columns.size();
  const std::size_t line_no = lines_.line_number();
  row.clear(n);
  bool non_finite = false;
  std::size_t pos = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t comma = line.find(',', pos);
    const bool last = i + 1 == n;
    if (!last && comma == std::string_view::npos)
      return fail(line_no, line.size() + 1,
                  "expected " + std::to_string(n) + " fields, found " + std::to_string(i + 1));
    if (last && comma != std::string_view::npos) {
      std::size_t found = n;
      for (std::size_t c = comma; c != std::string_view::npos; c = line.find(',', c + 1)) ++found;
      return fail(line_no, comma + 1, "expected " + std::to_string(n) + " fields, found " + std::to_string(found));
    }
    const std::string_view field = line.substr(pos, last ? std::string_view::npos : comma - pos);
    const std::string_view name = schema_.columns[i];
    if (!field.empty()) {
      double v = 0.0;
      if (!parse_double(field, v))
        return fail(line_no, pos + 1, "field '" + std::string(name) + "': not a number " + quoted(field));
      if (!std::isfinite(v)) {
        const std::string why = "field '" + std::string(name) + "': not finite " + quoted(field);
        if (!leniency_.keep_non_finite || i == 0) return fail(line_no, pos + 1, why);
        if (!non_finite) note_anomaly(line_no, pos + 1, why);
        non_finite = true;
      }
      row.set(i, v);
    } else if (i == 0) {
      return fail(line_no, 1, "field 't': empty, every row needs a time");
    }
    pos = comma + 1;
  }
  non_finite_rows_ += non_finite;
  if (rows_ > 0 && !(row.t() > last_t_)) {
    char msg[128];
    std::snprintf(msg, sizeof msg, "field 't': time not increasing (%.9g after %.9g)", row.t(), last_t_);
    if (!leniency_.keep_non_increasing_time) return fail(line_no, 1, msg);
    ++time_anomalies_;
    note_anomaly(line_no, 1, msg);
    ++rows_;
    return ReadStatus::Row;  // last_t_ stays: the next good row is judged against the latest good time
  }
  last_t_ = row.t();
  ++rows_;
  if (first_t_count_ < kIntervalRows) {
    first_t_[first_t_count_++] = row.t();
    if (first_t_count_ == kIntervalRows) return check_time_unit(line_no);
  }
  return ReadStatus::Row;
}

ReadStatus CsvReader::check_time_unit(std::size_t line_no) {
  if (!(schema_.max_median_interval_s > 0.0)) return ReadStatus::Row;
  std::array<double, kIntervalRows - 1> dt{};
  for (std::size_t i = 0; i + 1 < kIntervalRows; ++i) dt[i] = first_t_[i + 1] - first_t_[i];
  std::nth_element(dt.begin(), dt.begin() + dt.size() / 2, dt.end());
  const double median = dt[dt.size() / 2];
  if (median <= schema_.max_median_interval_s) return ReadStatus::Row;
  char msg[256];
  std::snprintf(msg, sizeof msg,
                "field 't': the first %zu rows advance a median %.6g s per row (%.3g Hz), more than the %.3g s "
                "any sensor of this file takes: t must be seconds (milliseconds read 1000x)",
                kIntervalRows, median, 1.0 / median, schema_.max_median_interval_s);
  return fail(line_no, 1, msg);
}

CsvWriter::CsvWriter(const CsvSchema& schema) : schema_(schema), buffer_(new char[kWriteBuffer]) {}

CsvWriter::~CsvWriter() { close(); }

bool CsvWriter::open(const std::string& path) {
  error_ = Diagnostic{path, 0, 0, {}};
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) {
    error_.message = std::string("cannot create: ") + std::strerror(errno);
    return false;
  }
  const std::string header = header_of(schema_) + '\n';
  std::memcpy(buffer_.get(), header.data(), header.size());
  used_ = header.size();
  return true;
}

bool CsvWriter::write(const CsvRow& row) {
  if (!file_) return false;
  if (kWriteBuffer - used_ < kMaxRowChars && !flush()) return false;
  char* out = buffer_.get() + used_;
  char* const end = buffer_.get() + kWriteBuffer;
  for (std::size_t i = 0; i < schema_.columns.size(); ++i) {
    if (i) *out++ = ',';
    if (!row.has(i)) continue;
    const ColumnFormat f = format_[i];
    std::to_chars_result r{};
    switch (f.style) {
      case ColumnFormat::Style::Shortest: r = std::to_chars(out, end, row.value[i]); break;
      case ColumnFormat::Style::Fixed:
        r = std::to_chars(out, end, row.value[i], std::chars_format::fixed, f.precision);
        break;
      case ColumnFormat::Style::Significant:
        r = std::to_chars(out, end, row.value[i], std::chars_format::general, f.precision);
        break;
    }
    if (r.ec != std::errc{}) {
      error_.message = "value too long to format";
      return false;
    }
    out = r.ptr;
  }
  *out++ = '\n';
  used_ = static_cast<std::size_t>(out - buffer_.get());
  return true;
}

bool CsvWriter::flush() {
  if (used_ == 0) return true;
  if (std::fwrite(buffer_.get(), 1, used_, file_) != used_) {
    error_.message = std::string("write failed: ") + std::strerror(errno);
    return false;
  }
  used_ = 0;
  return true;
}

bool CsvWriter::close() {
  if (!file_) return error_.message.empty();
  bool ok = flush();
  if (std::fclose(file_) != 0 && ok) {
    error_.message = std::string("close failed: ") + std::strerror(errno);
    ok = false;
  }
  file_ = nullptr;
  return ok;
}

}  // namespace sinu::dataset
