#pragma once
// Writes a raw recording. Records are buffered and handed to the kernel
// (write + fdatasync) whenever the buffer fills or one second of recorded
// time has passed since the last sync, so a crash or power cut loses at most
// the last second. No allocation after open().
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "hal/recording/recording_format.hpp"

namespace sinu::hal::rec {

class RecordingWriter {
 public:
  static constexpr TimeNs kSyncPeriodNs = 1'000'000'000;
  RecordingWriter();
  ~RecordingWriter();
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;

  /// Creates the file and writes its header. On false, error() says why.
  bool open(const std::string& path);
  /// Appends a record; payload of at most kMaxPayload bytes. Times should not
  /// decrease (the reader reports it if they do).
  bool append(Kind kind, TimeNs t_ns, std::span<const std::uint8_t> payload);
  /// Convenience for payloads made of a small prefix and a data block.
  bool append(Kind kind, TimeNs t_ns, std::span<const std::uint8_t> prefix, std::span<const std::uint8_t> data);
  /// Writes out everything buffered and syncs it to the disk.
  bool sync();
  bool close();
  bool is_open() const { return fd_ >= 0; }
  const std::string& error() const { return error_; }
  std::uint64_t records() const { return records_; }

 private:
  bool drain();

  int fd_ = -1;
  std::unique_ptr<std::uint8_t[]> buffer_;
  std::size_t used_ = 0;
  TimeNs last_sync_ns_ = 0;
  bool synced_once_ = false;
  std::uint64_t records_ = 0;
  std::string path_, error_;
};

}  // namespace sinu::hal::rec
