#pragma once
// The one CSV engine behind imu.csv and truth.csv (dataset-format.md):
// an exact header line, then rows of decimal numbers, first column `t`
// strictly increasing. An empty field is "no measurement": its bit in
// `present` is clear and its value is NaN, never zero.
//
// Reading streams through a LineReader (constant memory, no allocation per
// row); the first bad row stops the reader with a file:line:column Diagnostic.
#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "firmware/host/dataset/diagnostic.hpp"
#include "firmware/host/dataset/line_reader.hpp"

namespace sinu::dataset {

inline constexpr std::size_t kMaxCsvColumns = 16;

struct CsvSchema {
  std::string_view file_name;                  // "imu.csv", used in messages
  std::span<const std::string_view> columns;   // columns[0] is "t"
  // t in other units than seconds (ms read 1000x): the median interval of the
  // first rows above this is an error (0: not checked).
  double max_median_interval_s = 0.0;
};

struct CsvRow {
  std::array<double, kMaxCsvColumns> value{};
  std::uint32_t present = 0;  // bit i set: column i held a number
  bool has(std::size_t i) const { return (present >> i) & 1u; }
  double t() const { return value[0]; }
  void set(std::size_t i, double v) {
    value[i] = v;
    present |= 1u << i;
  }
  void clear(std::size_t n_columns);  // all columns empty (NaN)
};

enum class ReadStatus { Row, End, Error };

/// Parses one number the way C's strtod would, rejecting trailing garbage.
/// Fast path std::from_chars; strtod only for forms it does not take ("+1", hex).
bool parse_double(std::string_view field, double& out);

/// What a reader does with rows that break the contract in ways a live
/// stream can (a time that repeats or steps back, a NaN from a driver):
/// stop with an error (the default: `inspect` and `calibrate` validate), or
/// return them and count them (`replay`: the navigator drops and flags them).
struct CsvLeniency {
  bool keep_non_increasing_time = false;
  bool keep_non_finite = false;
};

class CsvReader {
 public:
  explicit CsvReader(const CsvSchema& schema, CsvLeniency leniency = {});
  /// Opens the file and checks the header. On false, error() says why.
  bool open(const std::string& path);
  /// Next row; on ReadStatus::Error see error(). Never allocates on success.
  ReadStatus next(CsvRow& row);
  const Diagnostic& error() const { return error_; }
  std::size_t rows() const { return rows_; }
  /// Rows kept despite a time not after the previous one, or a non-finite value.
  std::size_t time_anomalies() const { return time_anomalies_; }
  std::size_t non_finite_rows() const { return non_finite_rows_; }
  /// The first such row, file:line:column and why (empty message if none).
  const Diagnostic& first_anomaly() const { return first_anomaly_; }
  std::size_t line_number() const { return lines_.line_number(); }

 private:
  ReadStatus fail(std::size_t line, std::size_t column, std::string message);

  void note_anomaly(std::size_t line, std::size_t column, const std::string& message);

  CsvSchema schema_;
  CsvLeniency leniency_;
  LineReader lines_;
  std::string path_;
  Diagnostic error_, first_anomaly_;
  std::size_t time_anomalies_ = 0, non_finite_rows_ = 0;
  double last_t_ = 0.0;
  std::size_t rows_ = 0;
  static constexpr std::size_t kIntervalRows = 21;  // the first rows' times, for the units check
  std::array<double, kIntervalRows> first_t_{};
  std::size_t first_t_count_ = 0;
  /// The first rows' median interval against schema.max_median_interval_s.
  ReadStatus check_time_unit(std::size_t line_no);
};

/// How one column is printed: shortest round-trip (precision 0), or a fixed
/// number of decimals, or a number of significant digits.
struct ColumnFormat {
  enum class Style { Shortest, Fixed, Significant } style = Style::Shortest;
  int precision = 0;
};

class CsvWriter {
 public:
  explicit CsvWriter(const CsvSchema& schema);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  void set_format(std::size_t column, ColumnFormat format) { format_[column] = format; }
  /// Creates the file and writes the header. On false, error() says why.
  bool open(const std::string& path);
  /// Appends a row (absent columns as empty fields). Buffered, no allocation.
  bool write(const CsvRow& row);
  /// Flushes and closes; false if anything failed to reach the disk.
  bool close();
  const Diagnostic& error() const { return error_; }

 private:
  bool flush();

  CsvSchema schema_;
  std::array<ColumnFormat, kMaxCsvColumns> format_{};
  std::FILE* file_ = nullptr;
  std::unique_ptr<char[]> buffer_;
  std::size_t used_ = 0;
  Diagnostic error_;
};

}  // namespace sinu::dataset
