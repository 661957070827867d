#include "firmware/host/dataset/nmea_log.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>

namespace sinu::dataset {

bool NmeaLogReader::open(const std::string& path) {
  path_ = path;
  skipped_ = 0;
  have_last_ = false;
  first_skipped_ = {};
  if (!lines_.open(path)) {
    error_ = Diagnostic{path, 0, 0, std::string("cannot open: ") + std::strerror(errno)};
    return false;
  }
  return true;
}

void NmeaLogReader::skip(std::size_t column, const char* why) {
  if (skipped_++ == 0) first_skipped_ = Diagnostic{path_, lines_.line_number(), column, why};
}

ReadStatus NmeaLogReader::next(NmeaLogLine& out) {
  while (true) {
    std::string_view line;
    switch (lines_.next(line)) {
      case LineReader::Status::Line: break;
      case LineReader::Status::End: return ReadStatus::End;
      case LineReader::Status::TooLong:  // garbage without line breaks: counted, skipped to its end
        skip(0, "line longer than 4 KiB");
        continue;
      case LineReader::Status::IoError:
        error_ = Diagnostic{path_, lines_.line_number() + 1, 0, "read error"};
        return ReadStatus::Error;
    }
    const std::size_t comma = line.find(',');
    if (comma == std::string_view::npos) {
      skip(1, "no arrival time: expected 'time,sentence'");
      continue;
    }
    double t = 0.0;
    if (!parse_double(line.substr(0, comma), t) || !std::isfinite(t)) {
      skip(1, "arrival time is not a number");
      continue;
    }
    if (have_last_ && !(t > last_arrival_s_)) {
      skip(1, "arrival time not increasing");
      continue;
    }
    last_arrival_s_ = t;
    have_last_ = true;
    out.arrival_s = t;
    out.sentence = line.substr(comma + 1);
    return ReadStatus::Row;
  }
}

ReadStatus GpsLogReader::next(drivers::GpsFix& fix) {
  NmeaLogLine line;
  drivers::NmeaMessage msg;
  while (!ended_) {
    const ReadStatus s = log_.next(line);
    if (s == ReadStatus::Error) return s;
    if (s == ReadStatus::End) {
      ended_ = true;
      return assembler_.flush(fix) ? ReadStatus::Row : ReadStatus::End;
    }
    const auto r = parser_.parse(line.sentence, msg);
    if (r == drivers::ParseResult::Corrupt) {
      if (parser_.counters().corrupt() == 1)
        first_corrupt_ = Diagnostic{path_, static_cast<std::size_t>(log_.lines()), 0, parser_.last_error()};
      continue;
    }
    if (r == drivers::ParseResult::Message && assembler_.add(msg, line.arrival_s, fix)) return ReadStatus::Row;
  }
  return ReadStatus::End;
}

NmeaLogWriter::~NmeaLogWriter() { close(); }

bool NmeaLogWriter::open(const std::string& path) {
  error_ = Diagnostic{path, 0, 0, {}};
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) error_.message = std::string("cannot create: ") + std::strerror(errno);
  return file_ != nullptr;
}

bool NmeaLogWriter::write(double arrival_s, std::string_view sentence) {
  if (!file_) return false;
  if (std::fprintf(file_, "%.6f,%.*s\n", arrival_s, static_cast<int>(sentence.size()), sentence.data()) < 0) {
    error_.message = std::string("write failed: ") + std::strerror(errno);
    return false;
  }
  return true;
}

bool NmeaLogWriter::close() {
  if (!file_) return error_.message.empty();
  const bool ok = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok) error_.message = std::string("close failed: ") + std::strerror(errno);
  return ok;
}

}  // namespace sinu::dataset
