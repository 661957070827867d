#pragma once
// Buffered text output with a fixed buffer allocated once at open(): numbers
// are formatted with std::to_chars, so writing rows never allocates.
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

namespace sinu::board {

class TextSink {
 public:
  ~TextSink();
  bool open(const std::string& path);
  void text(std::string_view s);
  /// Fixed notation with `decimals` digits; NaN written as an empty field.
  void number(double v, int decimals);
  void comma() { text(","); }
  void end_row() { text("\n"); }
  /// Hands everything buffered to the operating system (a crash loses no more).
  void flush();
  /// Flushes and closes; false if any write failed.
  bool close();
  const std::string& path() const { return path_; }

 private:
  void write_buffer();
  std::FILE* file_ = nullptr;
  std::unique_ptr<char[]> buf_;
  std::size_t used_ = 0;
  bool failed_ = false;
  std::string path_;
};

}  // namespace sinu::board
