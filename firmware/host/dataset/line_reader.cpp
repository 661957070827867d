#include "firmware/host/dataset/line_reader.hpp"

#include <cstring>

namespace sinu::dataset {

namespace {
constexpr std::size_t kChunk = 256 * 1024;  // bytes read per refill
}

LineReader::LineReader(std::size_t max_line)
    : capacity_(max_line + kChunk), buffer_(new char[max_line + kChunk]) {}

LineReader::~LineReader() {
  if (file_) std::fclose(file_);
}

bool LineReader::open(const std::string& path) {
  if (file_) std::fclose(file_);
  file_ = std::fopen(path.c_str(), "rb");
  begin_ = end_ = 0;
  eof_ = false;
  line_number_ = 0;
  return file_ != nullptr;
}

bool LineReader::refill() {
  if (eof_ || !file_) return false;
  if (begin_ > 0) {  // slide the unread tail to the front
    std::memmove(buffer_.get(), buffer_.get() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  const std::size_t want = std::min(kChunk, capacity_ - end_);
  if (want == 0) return false;
  const std::size_t got = std::fread(buffer_.get() + end_, 1, want, file_);
  end_ += got;
  if (got < want) eof_ = true;
  return got > 0;
}

LineReader::Status LineReader::skip_long_line() {
  ++line_number_;
  while (true) {
    const void* nl = std::memchr(buffer_.get() + begin_, '\n', end_ - begin_);
    if (nl != nullptr) {
      begin_ = static_cast<std::size_t>(static_cast<const char*>(nl) - buffer_.get()) + 1;
      return Status::TooLong;
    }
    begin_ = end_;  // all of it belongs to the long line
    if (!refill()) return std::ferror(file_) ? Status::IoError : Status::TooLong;
  }
}

LineReader::Status LineReader::next(std::string_view& line) {
  if (!file_) return Status::IoError;
  const std::size_t max_line = capacity_ - kChunk;
  std::size_t scanned = begin_;  // bytes before this index hold no LF
  while (true) {
    const void* nl = std::memchr(buffer_.get() + scanned, '\n', end_ - scanned);
    if (nl != nullptr) {
      const auto stop = static_cast<std::size_t>(static_cast<const char*>(nl) - buffer_.get());
      std::size_t len = stop - begin_;
      if (len > 0 && buffer_[begin_ + len - 1] == '\r') --len;
      line = std::string_view(buffer_.get() + begin_, len);
      begin_ = stop + 1;
      ++line_number_;
      return len > max_line ? Status::TooLong : Status::Line;
    }
    if (end_ - begin_ > max_line) return skip_long_line();
    const std::size_t unread = end_ - begin_;
    if (!refill()) {
      if (std::ferror(file_)) return Status::IoError;
      if (begin_ == end_) return Status::End;
      std::size_t len = end_ - begin_;  // last line, no terminating LF
      if (buffer_[begin_ + len - 1] == '\r') --len;
      line = std::string_view(buffer_.get() + begin_, len);
      begin_ = end_;
      ++line_number_;
      return Status::Line;
    }
    scanned = begin_ + unread;  // refill() slid the unread bytes to the front
  }
}

}  // namespace sinu::dataset
