#pragma once
// gps.nmea: one sentence per line, prefixed by its arrival time and a comma:
//   1203.400,$GPGGA,101520.40,...*6A
// A line whose time prefix is unreadable, or whose time does not increase,
// is counted and skipped (the contract says corrupt lines never stop a
// reader); only an unreadable file is an error. Sentence-level corruption
// is the NMEA parser's to count.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include "drivers/gps/fix_assembler.hpp"
#include "drivers/gps/nmea_parser.hpp"
#include "firmware/host/dataset/csv_table.hpp"
#include "firmware/host/dataset/diagnostic.hpp"
#include "firmware/host/dataset/line_reader.hpp"

namespace sinu::dataset {

struct NmeaLogLine {
  double arrival_s = 0.0;
  std::string_view sentence;  // valid until the next call
};

class NmeaLogReader {
 public:
  bool open(const std::string& path);
  ReadStatus next(NmeaLogLine& out);
  const Diagnostic& error() const { return error_; }
  std::uint64_t lines() const { return lines_.line_number(); }
  std::uint64_t skipped_lines() const { return skipped_; }
  /// The first skipped line and why, for reports (empty message if none).
  const Diagnostic& first_skipped() const { return first_skipped_; }

 private:
  void skip(std::size_t column, const char* why);

  LineReader lines_{4096};
  std::string path_;
  Diagnostic error_, first_skipped_;
  double last_arrival_s_ = 0.0;
  bool have_last_ = false;
  std::uint64_t skipped_ = 0;
};

/// gps.nmea -> GpsFix stream: log lines -> NmeaParser -> FixAssembler.
class GpsLogReader {
 public:
  bool open(const std::string& path) {
    path_ = path;
    return log_.open(path);
  }
  /// Next assembled epoch; ReadStatus::End after the last one.
  ReadStatus next(drivers::GpsFix& fix);
  const NmeaLogReader& log() const { return log_; }
  const drivers::NmeaCounters& counters() const { return parser_.counters(); }
  /// Sentences that came after their epoch was emitted, or repeated its time (dropped).
  std::uint64_t late_sentences() const { return assembler_.late_sentences(); }
  /// Corrupt sentences plus skipped lines.
  std::uint64_t corrupt() const { return parser_.counters().corrupt() + log_.skipped_lines(); }
  const Diagnostic& error() const { return log_.error(); }
  /// The first corrupt sentence and why, for reports.
  const Diagnostic& first_corrupt() const { return first_corrupt_; }

 private:
  NmeaLogReader log_;
  drivers::NmeaParser parser_;
  drivers::FixAssembler assembler_;
  std::string path_;
  Diagnostic first_corrupt_;
  bool ended_ = false;
};

class NmeaLogWriter {
 public:
  ~NmeaLogWriter();
  bool open(const std::string& path);
  /// Writes "arrival,sentence\n"; arrival to the microsecond.
  bool write(double arrival_s, std::string_view sentence);
  bool close();
  const Diagnostic& error() const { return error_; }

 private:
  std::FILE* file_ = nullptr;
  Diagnostic error_;
};

}  // namespace sinu::dataset
