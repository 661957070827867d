#pragma once
// The loop's time per sample, from the data-ready edge's time stamp to the
// sample's outputs written: a fixed histogram (10 us bins up to 100 ms, the
// rest in one overflow bin) and the exact worst case. No allocation after
// construction.
#include <algorithm>
#include <array>
#include <cstdint>

#include "hal/clock.hpp"

namespace sinu::board {

class LoopStats {
 public:
  static constexpr hal::TimeNs kBinNs = 10'000;
  static constexpr std::size_t kBins = 10'000;  // 100 ms

  void add(hal::TimeNs elapsed_ns) {
    const hal::TimeNs e = std::max<hal::TimeNs>(0, elapsed_ns);
    ++bins_[std::min(kBins - 1, static_cast<std::size_t>(e / kBinNs))];
    worst_ns_ = std::max(worst_ns_, e);
    ++count_;
  }
  std::uint64_t count() const { return count_; }
  hal::TimeNs worst_ns() const { return worst_ns_; }
  /// The median to the bin's resolution (its upper edge); 0 without samples.
  hal::TimeNs median_ns() const {
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < kBins; ++i) {
      seen += bins_[i];
      if (2 * seen >= count_ && count_ > 0) return static_cast<hal::TimeNs>(i + 1) * kBinNs;
    }
    return 0;
  }

 private:
  std::array<std::uint32_t, kBins> bins_{};
  std::uint64_t count_ = 0;
  hal::TimeNs worst_ns_ = 0;
};

}  // namespace sinu::board
