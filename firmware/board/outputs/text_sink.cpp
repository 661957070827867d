#include "firmware/board/outputs/text_sink.hpp"

#include <charconv>
#include <cmath>
#include <cstring>

namespace sinu::board {

namespace {
constexpr std::size_t kBufferBytes = 1 << 16;
constexpr std::size_t kMaxNumberChars = 64;
}  // namespace

TextSink::~TextSink() { close(); }

bool TextSink::open(const std::string& path) {
  path_ = path;
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) return false;
  buf_ = std::make_unique<char[]>(kBufferBytes);
  used_ = 0;
  failed_ = false;
  return true;
}

void TextSink::write_buffer() {
  if (file_ && used_ > 0 && std::fwrite(buf_.get(), 1, used_, file_) != used_) failed_ = true;
  used_ = 0;
}

void TextSink::flush() {
  write_buffer();
  if (file_ && std::fflush(file_) != 0) failed_ = true;
}

void TextSink::text(std::string_view s) {
  if (!file_) return;
  if (used_ + s.size() > kBufferBytes) write_buffer();
  if (s.size() > kBufferBytes) {
    if (std::fwrite(s.data(), 1, s.size(), file_) != s.size()) failed_ = true;
    return;
  }
  std::memcpy(buf_.get() + used_, s.data(), s.size());
  used_ += s.size();
}

void TextSink::number(double v, int decimals) {
  if (!file_ || !std::isfinite(v)) return;
  if (used_ + kMaxNumberChars > kBufferBytes) write_buffer();
  char* begin = buf_.get() + used_;
  // |v| >= 1e15 would need more than kMaxNumberChars in fixed notation: use general.
  const auto res = std::abs(v) < 1e15 ? std::to_chars(begin, begin + kMaxNumberChars, v, std::chars_format::fixed, decimals)
                                      : std::to_chars(begin, begin + kMaxNumberChars, v);
  if (res.ec == std::errc()) used_ += static_cast<std::size_t>(res.ptr - begin);
}

bool TextSink::close() {
  if (!file_) return !failed_;
  write_buffer();
  if (std::fclose(file_) != 0) failed_ = true;
  file_ = nullptr;
  return !failed_;
}

}  // namespace sinu::board
