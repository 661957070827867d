#pragma once
// Groups decoded NMEA messages into epochs (sentences with the same UTC time)
// and emits one GpsFix per epoch. Time-less sentences (VTG, GSA) join the
// open epoch. An epoch is emitted
//   - as soon as the sentence type that ended the previous epoch arrives
//     (the receiver's cycle is learned, like gpsd's cycle-ender), or
//   - when a sentence with a different time arrives, or on flush().
#include <cstdint>

#include "drivers/gps/gps_fix.hpp"
#include "drivers/gps/nmea_messages.hpp"

namespace sinu::drivers {

class FixAssembler {
 public:
  /// Feeds one message that arrived at `arrival_s`. Returns true and fills
  /// `out` when an epoch completed.
  bool add(const NmeaMessage& msg, double arrival_s, GpsFix& out);
  /// Emits the open epoch, if any (end of stream).
  bool flush(GpsFix& out);
  std::uint64_t epochs() const { return epochs_; }

 private:
  void merge(const NmeaMessage& msg);
  bool emit(GpsFix& out);

  GpsFix open_{};
  bool is_open_ = false;
  bool has_time_ = false;
  std::size_t last_type_ = SIZE_MAX;   // variant index of the latest message in the open epoch
  std::size_t cycle_end_ = SIZE_MAX;   // variant index that ended the previous epoch
  std::uint64_t epochs_ = 0;
};

}  // namespace sinu::drivers
