#include "firmware/board/outputs/gps_time.hpp"

namespace sinu::board {

GpsWeekTime gps_week_time(std::int64_t utc_ms) {
  const std::int64_t gps_ms = utc_ms - kGpsEpochUnixS * 1'000 + kGpsMinusUtcS * 1'000;
  if (gps_ms < 0) return {};
  return {static_cast<std::uint16_t>(gps_ms / kMsPerGpsWeek), static_cast<std::uint32_t>(gps_ms % kMsPerGpsWeek)};
}

}  // namespace sinu::board
