#pragma once
// Groups decoded NMEA messages into epochs (sentences with the same UTC time)
// and emits one GpsFix per epoch. Time-less sentences (VTG, GSA) join the
// open epoch. An epoch is emitted
//   - as soon as the receiver's cycle-ending sentence type arrives (learned,
//     like gpsd's cycle-ender), or
//   - when a sentence with a different time arrives, or on flush().
// The cycle ender is learned from complete epochs only: an epoch that lacks
// it (a receiver that skips GST now and then) is closed by the next epoch's
// first sentence and leaves the ender unchanged; only kLowerAfter such epochs
// in a row (the receiver changed its output) lower it. A timed sentence that
// arrives after its epoch was emitted raises the ender to its type and is
// counted as late, never turned into an epoch of its own; so are the
// time-less sentences that follow it. A sentence type the emitted epoch
// already held is the receiver repeating that epoch (uav_log171 sends one
// GGA/RMC/GST epoch twice): dropped the same way, but the ender stands (once
// moved to GGA by the repeat, every later GGA + VTG epoch was emitted at its
// GGA and took the previous VTG's arrival time and velocity).
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
  /// Sentences that arrived after their epoch had been emitted (dropped): timed
  /// ones, repeats, and the time-less ones that followed them.
  std::uint64_t late_sentences() const { return late_; }

 private:
  static constexpr int kLowerAfter = 3;
  void merge(const NmeaMessage& msg);
  bool emit(GpsFix& out);
  void learn_cycle_end();

  GpsFix open_{};
  bool is_open_ = false;
  bool has_time_ = false;
  std::size_t last_type_ = SIZE_MAX;   // variant index of the latest message in the open epoch
  std::size_t cycle_end_ = SIZE_MAX;   // variant index that ends the receiver's epoch
  std::size_t short_end_ = SIZE_MAX;   // last type of the recent epochs that lacked the ender
  int short_epochs_ = 0;               // how many in a row
  std::uint32_t open_types_ = 0;       // bit per variant index: the types in the open epoch
  std::uint32_t emitted_types_ = 0;    // ... in the epoch last emitted (and its late sentences)
  bool dropping_ = false;              // after a late sentence, until a new time: its followers are late too
  bool have_emitted_ = false;
  UtcMs emitted_utc_ms_ = 0;
  std::uint64_t epochs_ = 0;
  std::uint64_t late_ = 0;
};

}  // namespace sinu::drivers
