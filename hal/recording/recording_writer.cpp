#include "hal/recording/recording_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace sinu::hal::rec {

namespace {
constexpr std::size_t kBufferSize = 64 * 1024;

void put_u16(std::uint8_t* p, std::uint16_t v) {
  p[0] = static_cast<std::uint8_t>(v);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
void put_u32(std::uint8_t* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
void put_u64(std::uint8_t* p, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
}  // namespace

RecordingWriter::RecordingWriter() : buffer_(new std::uint8_t[kBufferSize]) {}

RecordingWriter::~RecordingWriter() { close(); }

bool RecordingWriter::open(const std::string& path) {
  path_ = path;
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    error_ = path + ": cannot create: " + std::strerror(errno);
    return false;
  }
  std::uint8_t* h = buffer_.get();
  std::memset(h, 0, kFileHeaderSize);
  std::memcpy(h, kMagic.data(), kMagic.size());
  put_u16(h + 8, kVersion);
  used_ = kFileHeaderSize;
  records_ = 0;
  synced_once_ = false;
  return sync();
}

bool RecordingWriter::drain() {
  std::size_t done = 0;
  while (done < used_) {
    const ssize_t n = ::write(fd_, buffer_.get() + done, used_ - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error_ = path_ + ": write failed: " + std::strerror(errno);
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  used_ = 0;
  return true;
}

bool RecordingWriter::sync() {
  if (fd_ < 0) return false;
  if (!drain()) return false;
  if (::fdatasync(fd_) < 0 && errno != EINVAL) {  // EINVAL: a pipe or special file, nothing to sync
    error_ = path_ + ": fdatasync failed: " + std::strerror(errno);
    return false;
  }
  return true;
}

bool RecordingWriter::append(Kind kind, TimeNs t_ns, std::span<const std::uint8_t> payload) {
  return append(kind, t_ns, payload, {});
}

bool RecordingWriter::append(Kind kind, TimeNs t_ns, std::span<const std::uint8_t> prefix,
                             std::span<const std::uint8_t> data) {
  if (fd_ < 0) return false;
  const std::size_t length = prefix.size() + data.size();
  if (length > kMaxPayload) {
    error_ = path_ + ": record payload too long";
    return false;
  }
  const std::size_t total = kRecordHeaderSize + length + kRecordTrailerSize;
  if (used_ + total > kBufferSize && !drain()) return false;
  std::uint8_t* p = buffer_.get() + used_;
  p[0] = static_cast<std::uint8_t>(kind);
  put_u16(p + 1, static_cast<std::uint16_t>(length));
  put_u64(p + 3, static_cast<std::uint64_t>(t_ns));
  if (!prefix.empty()) std::memcpy(p + kRecordHeaderSize, prefix.data(), prefix.size());
  if (!data.empty()) std::memcpy(p + kRecordHeaderSize + prefix.size(), data.data(), data.size());
  put_u32(p + kRecordHeaderSize + length, crc32({p, kRecordHeaderSize + length}));
  used_ += total;
  ++records_;
  if (!synced_once_) {
    synced_once_ = true;
    last_sync_ns_ = t_ns;
  } else if (t_ns - last_sync_ns_ >= kSyncPeriodNs) {
    last_sync_ns_ = t_ns;
    return sync();
  }
  return true;
}

bool RecordingWriter::close() {
  if (fd_ < 0) return error_.empty();
  const bool ok = sync();
  ::close(fd_);
  fd_ = -1;
  return ok;
}

}  // namespace sinu::hal::rec
