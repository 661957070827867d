#pragma once
// Streams a text file line by line through one fixed buffer: memory stays the
// same whatever the file's length. Lines end in LF or CR LF; neither is part
// of the returned view. The view is valid until the next call.
// A line longer than max_line is TooLong wherever it falls in the file: it
// is skipped up to its LF and counted as a line, and reading can go on.
#include <cstddef>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

namespace sinu::dataset {

class LineReader {
 public:
  enum class Status { Line, End, TooLong, IoError };

  /// `max_line` bounds one line; the buffer is allocated once, here.
  explicit LineReader(std::size_t max_line = 64 * 1024);
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  /// Opens `path`; false if it cannot be opened (see errno).
  bool open(const std::string& path);
  bool is_open() const { return file_ != nullptr; }
  Status next(std::string_view& line);
  /// 1-based number of the line last returned.
  std::size_t line_number() const { return line_number_; }

 private:
  bool refill();
  Status skip_long_line();

  std::FILE* file_ = nullptr;
  std::size_t capacity_;
  std::unique_ptr<char[]> buffer_;
  std::size_t begin_ = 0, end_ = 0;
  bool eof_ = false;
  std::size_t line_number_ = 0;
};

}  // namespace sinu::dataset
