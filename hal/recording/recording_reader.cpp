#include "hal/recording/recording_reader.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

namespace sinu::hal::rec {

namespace {
std::uint16_t get_u16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | (p[1] << 8)); }
std::uint32_t get_u32(const std::uint8_t* p) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
std::uint64_t get_u64(const std::uint8_t* p) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
}  // namespace

bool RecordingReader::open(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    message_ = path + ": cannot open: " + std::strerror(errno);
    return false;
  }
  bytes_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  name_ = path;
  data_ = bytes_;
  return check_header();
}

bool RecordingReader::open_bytes(std::span<const std::uint8_t> bytes, const std::string& name) {
  bytes_.clear();
  data_ = bytes;
  name_ = name;
  return check_header();
}

bool RecordingReader::check_header() {
  offset_ = 0;
  records_ = unknown_ = reversals_ = 0;
  last_t_ns_ = 0;
  stopped_ = false;
  message_.clear();
  if (data_.size() < kFileHeaderSize || std::memcmp(data_.data(), kMagic.data(), kMagic.size()) != 0) {
    message_ = name_ + ": not a sinu raw recording (bad magic)";
    return false;
  }
  version_ = get_u16(data_.data() + 8);
  if (version_ == 0 || version_ > kVersion) {
    message_ = name_ + ": recording version " + std::to_string(version_) + " is newer than this sinu reads (" +
               std::to_string(kVersion) + ")";
    return false;
  }
  offset_ = kFileHeaderSize;
  return true;
}

ReadStatus RecordingReader::next(Record& out) {
  while (true) {
    if (stopped_) return stop_;
    const std::size_t left = data_.size() - offset_;
    if (left == 0) {
      stopped_ = true;
      return stop_ = ReadStatus::End;
    }
    const std::uint8_t* p = data_.data() + offset_;
    const std::size_t length = left >= kRecordHeaderSize ? get_u16(p + 1) : 0;
    if (left < kRecordHeaderSize || left < kRecordHeaderSize + length + kRecordTrailerSize) {
      stopped_ = true;
      message_ = name_ + ": truncated: last whole record ends at byte " + std::to_string(offset_) + " after " +
                 std::to_string(records_) + " records; " + std::to_string(left) + " bytes of a partial record dropped";
      return stop_ = ReadStatus::Truncated;
    }
    const std::size_t body = kRecordHeaderSize + length;
    if (length > kMaxPayload || get_u32(p + body) != crc32({p, body})) {
      stopped_ = true;
      message_ = name_ + ": corrupt record at byte " + std::to_string(offset_) + " (record " +
                 std::to_string(records_ + 1) + "): CRC mismatch";
      return stop_ = ReadStatus::Corrupt;
    }
    offset_ += body + kRecordTrailerSize;
    if (!is_known(p[0])) {  // a newer writer's record kind: skip it, count it
      ++unknown_;
      continue;
    }
    out.kind = static_cast<Kind>(p[0]);
    out.t_ns = static_cast<TimeNs>(get_u64(p + 3));
    out.payload = {p + kRecordHeaderSize, length};
    if (records_ > 0 && out.t_ns < last_t_ns_) ++reversals_;
    last_t_ns_ = out.t_ns;
    ++records_;
    return ReadStatus::Record;
  }
}

}  // namespace sinu::hal::rec
