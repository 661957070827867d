#pragma once
// Reads a raw recording (docs/recording.md) record by record. A file cut
// short (crash, power cut) reads up to its last whole record and then says
// Truncated; a record whose CRC fails stops the reader with Corrupt and the
// byte offset. Host-side: the whole file is held in memory.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "hal/recording/recording_format.hpp"

namespace sinu::hal::rec {

enum class ReadStatus { Record, End, Truncated, Corrupt };

class RecordingReader {
 public:
  /// Reads the file and checks its header. On false, message() says why.
  bool open(const std::string& path);
  /// Same, from bytes in memory (fuzzing, tests); `name` is used in messages.
  bool open_bytes(std::span<const std::uint8_t> bytes, const std::string& name = "<memory>");
  /// Next record. Record's payload stays valid while the reader lives.
  ReadStatus next(Record& out);
  /// Why the reader stopped (Truncated / Corrupt) or failed to open.
  const std::string& message() const { return message_; }
  std::uint64_t records() const { return records_; }
  std::uint16_t version() const { return version_; }
  std::uint64_t unknown_records() const { return unknown_; }
  std::uint64_t time_reversals() const { return reversals_; }

 private:
  bool check_header();

  std::vector<std::uint8_t> bytes_;
  std::span<const std::uint8_t> data_;
  std::size_t offset_ = 0;
  std::string name_, message_;
  std::uint16_t version_ = 0;
  std::uint64_t records_ = 0, unknown_ = 0, reversals_ = 0;
  TimeNs last_t_ns_ = 0;
  bool stopped_ = false;
  ReadStatus stop_ = ReadStatus::End;
};

}  // namespace sinu::hal::rec
